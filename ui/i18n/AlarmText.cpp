#include "ui/i18n/AlarmText.h"

#include "ui/i18n/Language.h"

namespace m350::ui {

QString AlarmText::message(const Alarm& alarm) {
    if (alarm.messageId.empty() || findMessagePattern(alarm.messageId) == nullptr) {
        return QString::fromStdString(alarm.message);
    }
    // translations/messages.tsv, the table the core and m350-sim say their messages from
    const MessageLanguage language =
        Language::panelLanguage() == QLatin1String("en") ? MessageLanguage::English : MessageLanguage::Chinese;
    return QString::fromStdString(messageText(alarm.messageId, alarm.messageArguments, language));
}

QString AlarmText::located(const Alarm& alarm) {
    const QString text = message(alarm);
    if (alarm.file.empty()) {
        return text;
    }
    return QStringLiteral("%1:%2:%3: %4").arg(QString::fromStdString(alarm.file)).arg(alarm.line).arg(alarm.column).arg(text);
}

} // namespace m350::ui
