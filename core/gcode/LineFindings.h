#pragma once

#include "core/common/Message.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/Token.h"

#include <cstdint>
#include <string>
#include <vector>

namespace m350::gcode {

// What the parser finds on the line it is reading, added to the file's findings with the file's
// name and the line's number: the syntax error that abandons the line (fail throws Failure, and
// the parser goes on at the next line), the lint finding that makes the block suspect, and notes
// that change nothing.
class LineFindings {
public:
    struct Failure {};

    LineFindings(std::vector<Diagnostic>& diagnostics, std::string fileName)
        : diagnostics_(diagnostics), fileName_(std::move(fileName)) {}

    // A new line: its number for the findings; no lint finding yet.
    void startLine(std::uint32_t lineNumber) {
        lineNumber_ = lineNumber;
        if (!lastLint_.message.empty()) { // few lines have one: no empty finding assigned to each
            lastLint_ = {};
        }
    }

    [[noreturn]] void fail(const Token& at, std::string message) { fail(at.column, std::move(message)); }
    [[noreturn]] void fail(std::uint32_t column, std::string message);
    [[noreturn]] void fail(const Token& at, const Message& words) { fail(at.column, words); }
    [[noreturn]] void fail(std::uint32_t column, const Message& words);
    // A syntax error that ends the line without abandoning a parse under way (a line refused unread).
    void refuse(std::uint32_t column, std::string message);
    void lint(std::uint32_t column, std::string message);
    void lint(std::uint32_t column, const Message& words);
    void note(std::uint32_t column, std::string message);
    void note(std::uint32_t column, const Message& words);

    // The lint finding of the line (its message empty when none).
    const Diagnostic& lastLint() const { return lastLint_; }
    bool linted() const { return !lastLint_.message.empty(); }

private:
    std::vector<Diagnostic>& diagnostics_;
    std::string fileName_;
    std::uint32_t lineNumber_ = 0;
    Diagnostic lastLint_;
};

} // namespace m350::gcode
