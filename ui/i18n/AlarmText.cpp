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
