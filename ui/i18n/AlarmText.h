#pragma once

#include "core/common/Alarm.h"

#include <QString>

namespace m350::ui {

// An alarm's message in the panel's language: the alarms that carry a message id
// (Alarm::messageId) are said from the message table (translations/messages.tsv, core/common/
// Message.h) in the language Language::set chose; the others by the core's own message.
class AlarmText {
public:
    static QString message(const Alarm& alarm);
    // "file:line:column: message" when the alarm has a place.
    static QString located(const Alarm& alarm);
};

} // namespace m350::ui
