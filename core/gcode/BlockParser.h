#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/BlockStorage.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Diagnostic.h"
#include "core/gcode/Expression.h"
#include "core/gcode/ExpressionParser.h"
#include "core/gcode/Lexer.h"
#include "core/gcode/LineChecks.h"
#include "core/gcode/LineFindings.h"
#include "core/gcode/LineTokens.h"
#include "core/gcode/PlainBlockParser.h"
#include "core/gcode/StatementParser.h"
#include "core/gcode/Token.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode {

// Parses the tokens of one line into a Block: labels, statements, assignments and words, their
// expressions read by an ExpressionParser. On the first error the line is abandoned (recovery is per block), so `check` still reports the
// errors of every other line.
class BlockParser {
public:
    BlockParser(const Dialect& dialect, BlockStorage& storage, std::vector<Diagnostic>& diagnostics,
                std::string fileName, std::uint32_t fileIndex);

    // Writes the line's block to `out` (which may be raw memory, such as the next slot of a
    // BlockList); false, and `out` untouched, for a line without content (blank, comment only, `%`)
    // or with a syntax error. LineEnd::Follows lets plain lines be read in place.
    bool parse(std::string_view line, std::uint32_t lineNumber, Block& out, LineEnd lineEnd = LineEnd::Unknown);
    std::optional<Block> parse(std::string_view line, std::uint32_t lineNumber);
    // The next line of `lines`, when the fast path reads it in place (a plain line followed by a
    // line end): then `line` is set and passed in `lines`. Declined (nothing passed) otherwise.
    PlainResult parseAhead(LineSplitter& lines, std::uint32_t lineNumber, Block& out, std::string_view& line) {
        const char* text = lines.lineAhead();
        if (!plainPath_ || comment_.open || text == nullptr) {
            return PlainResult::Declined;
        }
        std::size_t length = 0;
        const PlainResult result = parsePlainLine(text, dialect_, {fileIndex_, lineNumber, 0}, storage_, out, length);
        if (result != PlainResult::Declined) {
            line = lines.skipLine(length);
        }
        return result;
    }

    // Plain-word lines take a fast path by default; tests turn it off to compare both paths.
    void setPlainPath(bool enabled) { plainPath_ = enabled; }
    bool plainPath() const { return plainPath_; }

    // The lint finding of the block just parsed (empty when none).
    const Diagnostic& lastLint() const { return findings_.lastLint(); }

    // Whether the line just parsed, when it had an error, begins with an N or O number (a line a
    // jump or a call may reach).
    bool lastLineLabelled() const { return tokens_.startsLabelled(); }

    // A `/* */` comment still open after the last line parsed, and where its `/*` is.
    bool commentOpen() const { return comment_.open; }
    SourceLocation commentStart() const { return commentStart_; }

private:
    std::optional<Block> parseGeneral(std::string_view line, std::uint32_t lineNumber);


    void parseStatement(Block& block);
    void parseIf(Block& block);
    void parseWhile(Block& block);
    void parseItems(Block& block);
    Assignment parseAssignment();
    Word parseWord();
    ExprId parseCondition(const char* statement);
    int parseLoopId(const char* keyword);
    ExprId parseGotoTarget();
    std::int32_t labelNumber(const Token& number, const char* what);


    const Dialect& dialect_;
    BlockStorage& storage_;
    ExpressionPool& pool_; // storage_.expressions
    LineFindings findings_;
    std::uint32_t fileIndex_;

    LineTokens tokens_;
    ExpressionParser expressions_; // over tokens_ and findings_
    StatementParser statements_;   // POPEN PCLOS DPRNT BPRNT and the Modbus statements
    LineChecks checks_;
    std::vector<Assignment> assignments_; // of the block being parsed, stored when it parses
    BlockCommentState comment_;
    SourceLocation commentStart_;
    bool plainPath_ = true;
};

} // namespace m350::gcode
