#include "ui/i18n/AlarmText.h"

namespace m350::ui {

namespace {

QString words(const std::string& id) {
    if (id == "modbus_read_no_answer") {
        return AlarmText::tr("MGETDATA: Modbus slave %1 did not answer within %2 s; on the controller this hangs "
                             "MGETDATA until a reboot (modbus.toml declares no [slave.%1])");
    }
    if (id == "modbus_write_no_answer") {
        return AlarmText::tr("MSETDATA: Modbus slave %1 did not answer within %2 s (modbus.toml declares no [slave.%1])");
    }
    if (id == "setter_crash") {
        return AlarmText::tr("G00 drove T%1 %2 mm into the tool setter, below its trip point: a rapid must stop above "
                             "the setter, only G31 may touch it");
    }
    if (id == "tool_length_unset") {
        return AlarmText::tr("T%1 turns with no Z offset (param %2 = 0): set the tool before it cuts");
    }
    if (id == "tool_unsure") {
        return AlarmText::tr("The change to T%1 was stopped: the target tool [T%1] may differ from the current one [T%2]; "
                             "handle it by hand and enter the tool the spindle holds");
    }
    if (id == "tool_unsure_refused") {
        return AlarmText::tr("No tool change before the operator enters the tool the spindle holds: a change to T%1 "
                             "was stopped");
    }
    return {};
}

} // namespace

QString AlarmText::message(const Alarm& alarm) {
    QString text = words(alarm.messageId);
    if (text.isEmpty()) {
        return QString::fromStdString(alarm.message);
    }
    for (const std::string& argument : alarm.messageArguments) {
        text = text.arg(QString::fromStdString(argument));
    }
    return text;
}

QString AlarmText::located(const Alarm& alarm) {
    const QString text = message(alarm);
    if (alarm.file.empty()) {
        return text;
    }
    return QStringLiteral("%1:%2:%3: %4").arg(QString::fromStdString(alarm.file)).arg(alarm.line).arg(alarm.column).arg(text);
}

} // namespace m350::ui
