#pragma once

#include "core/common/Message.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Token.h"

#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode {

// A `/* */` comment (m350) may run over several lines: what one line leaves open for the next.
struct BlockCommentState {
    bool open = false;
    bool openedOnThisLine = false; // the `/*` still open is on the line just tokenized, at `column`
    std::uint32_t column = 0;
};

// Splits one line of program text into tokens. Words may be packed without spaces
// (`G91G31X-#2Y#3`): a run of letters is one keyword (`GOTO`, `WHILE`, `EQ`), several packed
// keywords (`LEABS` in `IF[#10LEABS[#11]]`) or, when it is a single letter, an address. On FANUC,
// spaces are insignificant outside comments (`GO TO 290`, `X 1 0 . 5`).
class Lexer {
public:
    explicit Lexer(const Dialect& dialect) : dialect_(dialect) {}

    // Fills `out` (cleared first); the last token is always End. Reusing `out` across lines keeps
    // lexing free of allocations. `comment` carries a `/* */` comment from line to line.
    void tokenize(std::string_view line, std::vector<Token>& out, BlockCommentState& comment) const;
    void tokenize(std::string_view line, std::vector<Token>& out) const;
    std::vector<Token> tokenize(std::string_view line) const;

    // What is wrong with a token whose issue is not None, in the operator's terms.
    std::string issueMessage(const Token& token, std::string_view line) const;
    // The same by message id (core/common/Message.h); an empty id for a token with no issue.
    Message issueWords(const Token& token, std::string_view line) const;

private:
    const Dialect& dialect_;
};

} // namespace m350::gcode
