#include "ui/session/MachineEventLog.h"

#include "ui/i18n/AlarmText.h"
#include "ui/session/SessionLog.h"

#include <array>

namespace m350::ui {

void MachineEventLog::noteAlarm(bool alarmed, const std::function<std::optional<Alarm>()>& inForce, SessionLog& log) {
    if (alarmed && !alarmLogged_) {
        if (const std::optional<Alarm> alarm = inForce()) {
            QString where = alarm->file.empty() ? QString()
                                                : QStringLiteral("%1:%2: ").arg(QString::fromStdString(alarm->file)).arg(alarm->line);
            log.record("alarm", where + AlarmText::message(*alarm));
        }
    }
    alarmLogged_ = alarmed;
}

// The event names the level, the detail the number, the values and the place.
void MachineEventLog::noteParameterChanges(const std::vector<controller::ParameterWrites::Change>& changes, SessionLog& log) {
    static constexpr std::array<const char*, 4> kEvents{"param_guest", "param_operator", "param_admin", "param_super"};
    for (const controller::ParameterWrites::Change& change : changes) {
        QString detail = QStringLiteral("[%1] %2 -> %3")
                             .arg(change.number)
                             .arg(QString::number(change.before, 'g', 10), QString::number(change.after, 'g', 10));
        if (!change.place.empty()) {
            detail += QStringLiteral(" (%1)").arg(QString::fromStdString(change.place));
        }
        log.record(kEvents[static_cast<std::size_t>(change.level)], detail);
    }
}

} // namespace m350::ui
