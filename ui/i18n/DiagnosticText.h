#pragma once

#include "core/gcode/Diagnostic.h"

#include <QString>

namespace m350::ui {

// A parser or checker finding in the panel's language: the findings that carry a message id
// (gcode::Diagnostic::messageId) are said from the message table, as AlarmText says alarms; the
// others by their English message.
class DiagnosticText {
public:
    static QString message(const gcode::Diagnostic& diagnostic);
    // "file:line:column: message", as m350-sim check says it.
    static QString located(const gcode::Diagnostic& diagnostic);
};

} // namespace m350::ui
