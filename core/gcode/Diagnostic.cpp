#include "core/gcode/Diagnostic.h"

#include "core/common/EchoText.h"

#include <algorithm>

namespace m350::gcode {

std::string formatDiagnostic(const Diagnostic& d) {
    std::string out = d.file + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) + ": ";
    if (d.severity == Severity::Warning) {
        out += "warning: ";
    }
    return out + d.message;
}

Diagnostic diagnostic(Severity severity, DiagnosticKind kind, std::string file, std::uint32_t line,
                      std::uint32_t column, const Message& words) {
    Diagnostic d{severity, kind, std::move(file), line, column, words.english()};
    d.messageId = words.id;
    d.messageArguments = words.arguments;
    std::string clipped = clipEcho(d.message);
    if (clipped != d.message) { // a long echo of the line: its pieces are clipped in every language
        d.message = std::move(clipped);
        for (std::string& argument : d.messageArguments) {
            argument = clipEcho(std::move(argument));
        }
    }
    return d;
}

std::string diagnosticText(const Diagnostic& d, MessageLanguage language) {
    if (d.messageId.empty() || language == MessageLanguage::English) {
        return d.message;
    }
    return messageText(d.messageId, d.messageArguments, language);
}

std::string formatDiagnostic(const Diagnostic& d, MessageLanguage language) {
    if (language == MessageLanguage::English || d.messageId.empty()) {
        return formatDiagnostic(d);
    }
    std::string out = d.file + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) + ": ";
    if (d.severity == Severity::Warning) {
        out += "警告: ";
    }
    return out + diagnosticText(d, language);
}

bool hasBlockingError(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) {
        return d.severity == Severity::Error && d.kind == DiagnosticKind::Syntax;
    });
}

} // namespace m350::gcode
