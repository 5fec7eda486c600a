#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <string>
#include <vector>

namespace m350::gcode {

// Where a token or block comes from. `file` indexes Program::files; line and column are 1-based,
// the column counted in characters (code points) of the UTF-8 text.
struct SourceLocation {
    std::uint32_t file = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

enum class Severity { Error, Warning };

// Syntax errors stop a program from running at all. Flow and lint findings (a GOTO with no label,
// a pocket table added instead of indexed) are errors for `check` but, as on the real controller,
// only become alarms when `run` reaches them.
enum class DiagnosticKind { Syntax, Flow, Lint };

struct Diagnostic {
    Severity severity = Severity::Error;
    DiagnosticKind kind = DiagnosticKind::Syntax;
    std::string file;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::string message;
    bool unreadable = false; // the file could not be read or decoded: a file error, not a syntax error
    std::uint64_t omitted = 0; // > 0: this note stands for that many findings left out (DiagnosticCap)
    // The message's words by id (core/common/Message.h) for the panel and `m350-sim --lang`;
    // `message` is its English.
    std::string messageId{};
    std::vector<std::string> messageArguments{};
};

// A finding said by a message of the table: `message` is its English (clipped as an echo is).
Diagnostic diagnostic(Severity severity, DiagnosticKind kind, std::string file, std::uint32_t line,
                      std::uint32_t column, const Message& words);

// "file:line:col: message", the form compilers use, so editors can jump to it.
std::string formatDiagnostic(const Diagnostic& diagnostic);
// The same in a language: the message by its id, the English `message` for a finding without one.
std::string formatDiagnostic(const Diagnostic& diagnostic, MessageLanguage language);
std::string diagnosticText(const Diagnostic& diagnostic, MessageLanguage language);

bool hasBlockingError(const std::vector<Diagnostic>& diagnostics);

} // namespace m350::gcode
