#pragma once

// Shared by the parser tests: parse a text into a Program with its diagnostics, and render
// expression trees as text so a test compares a whole tree at once.

#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode::support {

struct Parsed {
    Program program;
    std::vector<Diagnostic> diagnostics;
};

inline Parsed parse(std::string_view text, const Dialect& dialect, const std::string& file = "test.nc") {
    Parsed p;
    Parser parser(dialect);
    parser.addFile(p.program, file, text, FileRole::Main);
    parser.finish(p.program);
    p.diagnostics = parser.diagnostics();
    return p;
}

inline std::string listDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics) {
        out += formatDiagnostic(d) + "\n";
    }
    return out;
}

// Parses a program that must be clean: every diagnostic fails the test.
inline Parsed parseClean(std::string_view text, const Dialect& dialect, const std::string& file = "test.nc") {
    Parsed p = parse(text, dialect, file);
    EXPECT_TRUE(p.diagnostics.empty()) << listDiagnostics(p.diagnostics);
    return p;
}

// The program must have exactly one diagnostic, of `kind` at `line`:`column`, whose message starts
// with `messageStart`; `context` names the case in a failure.
inline void expectOneDiagnostic(const Parsed& p, DiagnosticKind kind, std::uint32_t line, std::uint32_t column,
                                const std::string& messageStart, const std::string& context = {}) {
    ASSERT_EQ(p.diagnostics.size(), 1u) << context << "\n" << listDiagnostics(p.diagnostics);
    const Diagnostic& d = p.diagnostics.front();
    EXPECT_EQ(d.kind, kind) << context << ": " << d.message;
    EXPECT_EQ(d.line, line) << context << ": " << d.message;
    EXPECT_EQ(d.column, column) << context << ": " << d.message;
    EXPECT_EQ(d.message.rfind(messageStart, 0), 0u) << context << ": " << d.message;
}

// Renders an expression tree with every binary node parenthesised: `(#1 + (2 * 3))`.
inline std::string show(const Program& program, ExprId id) {
    if (id == kNoExpr) {
        return "<none>";
    }
    const ExprNode& n = program.expressions[id];
    char buffer[32];
    switch (n.kind) {
    case ExprKind::Number:
        std::snprintf(buffer, sizeof buffer, "%g", n.number);
        return buffer;
    case ExprKind::Variable:
        if (n.lhs != kNoExpr) {
            return "#[" + show(program, n.lhs) + "]";
        }
        std::snprintf(buffer, sizeof buffer, "#%g", n.number);
        return buffer;
    case ExprKind::Unary:
        return (static_cast<UnaryOp>(n.op) == UnaryOp::Negate ? "-" : "+") + show(program, n.lhs);
    case ExprKind::Binary: {
        static const char* ops[] = {"+", "-", "*", "/", "MOD", "AND", "OR", "XOR", "==", "!=", "<", ">", "<=", ">="};
        return "(" + show(program, n.lhs) + " " + ops[n.op] + " " + show(program, n.rhs) + ")";
    }
    case ExprKind::Function: {
        static const char* names[] = {"ABS",   "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT",
                                      "ROUND", "FIX", "FUP", "LN",  "EXP",  "BIN",  "BCD"};
        std::string out = std::string(names[n.op]) + "[" + show(program, n.lhs);
        if (n.rhs != kNoExpr) {
            out += "," + show(program, n.rhs);
        }
        return out + "]";
    }
    }
    return "?";
}

// A word's value: its plain number, or its expression as show() renders it.
inline std::string show(const Program& program, const Word& word) {
    if (!word.isNumber()) {
        return show(program, word.value);
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", word.number);
    return buffer;
}

} // namespace m350::gcode::support
