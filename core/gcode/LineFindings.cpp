#include "core/gcode/LineFindings.h"

#include "core/common/EchoText.h"

namespace m350::gcode {

void LineFindings::fail(std::uint32_t column, std::string message) {
    refuse(column, std::move(message));
    throw Failure{};
}

void LineFindings::fail(std::uint32_t column, const Message& words) {
    diagnostics_.push_back(diagnostic(Severity::Error, DiagnosticKind::Syntax, fileName_, lineNumber_, column, words));
    throw Failure{};
}

void LineFindings::refuse(std::uint32_t column, std::string message) {
    diagnostics_.push_back(
        {Severity::Error, DiagnosticKind::Syntax, fileName_, lineNumber_, column, clipEcho(std::move(message))});
}

void LineFindings::lint(std::uint32_t column, std::string message) {
    diagnostics_.push_back(
        {Severity::Error, DiagnosticKind::Lint, fileName_, lineNumber_, column, clipEcho(std::move(message))});
    lastLint_ = diagnostics_.back();
}

void LineFindings::lint(std::uint32_t column, const Message& words) {
    diagnostics_.push_back(diagnostic(Severity::Error, DiagnosticKind::Lint, fileName_, lineNumber_, column, words));
    lastLint_ = diagnostics_.back();
}

void LineFindings::note(std::uint32_t column, std::string message) {
    diagnostics_.push_back(
        {Severity::Warning, DiagnosticKind::Lint, fileName_, lineNumber_, column, clipEcho(std::move(message))});
}

void LineFindings::note(std::uint32_t column, const Message& words) {
    diagnostics_.push_back(diagnostic(Severity::Warning, DiagnosticKind::Lint, fileName_, lineNumber_, column, words));
}

} // namespace m350::gcode
