#include "core/gcode/Diagnostic.h"

#include <algorithm>

namespace m350::gcode {

std::string formatDiagnostic(const Diagnostic& d) {
    std::string out = d.file + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) + ": ";
    if (d.severity == Severity::Warning) {
        out += "warning: ";
    }
    return out + d.message;
}

bool hasBlockingError(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) {
        return d.severity == Severity::Error && d.kind == DiagnosticKind::Syntax;
    });
}

} // namespace m350::gcode
