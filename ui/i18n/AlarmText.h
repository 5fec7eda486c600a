#pragma once

#include "core/common/Alarm.h"

#include <QCoreApplication>
#include <QString>

namespace m350::ui {

// An alarm's message in the panel's language: the alarms that carry a message id
// (Alarm::messageId) are said from their translated words with their arguments filled in; the
// others by the core's own message.
class AlarmText {
    Q_DECLARE_TR_FUNCTIONS(m350::ui::AlarmText)
public:
    static QString message(const Alarm& alarm);
    // "file:line:column: message" when the alarm has a place.
    static QString located(const Alarm& alarm);
};

} // namespace m350::ui
