#include "ui/i18n/DiagnosticText.h"

#include "ui/i18n/Language.h"

namespace m350::ui {

QString DiagnosticText::message(const gcode::Diagnostic& diagnostic) {
    return QString::fromStdString(gcode::diagnosticText(diagnostic, Language::messageLanguage()));
}

QString DiagnosticText::located(const gcode::Diagnostic& diagnostic) {
    return QString::fromStdString(gcode::formatDiagnostic(diagnostic, Language::messageLanguage()));
}

} // namespace m350::ui
