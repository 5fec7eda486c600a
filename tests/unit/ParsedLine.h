#pragma once

// One program line and the parts of the parser that read it (tokens, findings, expressions,
// statements, checks), for the tests of those parts. Not to be copied: the tokens point into `text`.
#include "core/gcode/LineChecks.h"
#include "core/gcode/StatementParser.h"

#include <string>
#include <utility>
#include <vector>

namespace m350::test {

struct ParsedLine {
    std::string text;
    std::vector<gcode::Diagnostic> found;
    gcode::BlockStorage storage;
    gcode::LineTokens tokens;
    gcode::LineFindings findings{found, "part.nc"};
    gcode::ExpressionParser expressions;
    gcode::StatementParser statements;
    gcode::LineChecks checks;
    gcode::BlockCommentState comment;

    ParsedLine(const gcode::Dialect& dialect, std::string line)
        : text(std::move(line)), expressions(dialect, storage.expressions, tokens, findings),
          statements(dialect, storage, tokens, findings, expressions),
          checks(dialect, storage.expressions, tokens, findings) {
        findings.startLine(1);
        tokens.read(gcode::Lexer(dialect), text, comment);
        expressions.startLine();
    }
    ParsedLine(const ParsedLine&) = delete;
    ParsedLine& operator=(const ParsedLine&) = delete;
};

} // namespace m350::test
