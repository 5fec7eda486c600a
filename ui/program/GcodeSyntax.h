#pragma once

#include <QStringView>

#include <cstdint>
#include <vector>

namespace m350::gcode {
struct Dialect;
}

namespace m350::ui {

// The editor's colouring of one line of either dialect: G/M words, other addresses, numbers,
// #variables, keywords (IF GOTO WHILE DO END AND OR ..., also packed as `LEABS`), functions, N/O
// labels, comments (`( )`, and on the M350 `;`, `//` and `/* */` across lines, by the parser's
// rules) and the texts of #1503/#1505 messages. A scanner, not the parser: it runs on each line
// shown, so it must be cheap.
class GcodeSyntax {
public:
    enum class Kind : std::uint8_t { Word, Address, Number, Variable, Keyword, Function, Label, Comment, Message };
    struct Span {
        int start;
        int length;
        Kind kind;
    };
    explicit GcodeSyntax(const gcode::Dialect& dialect);

    // Colours `line` into `out` (cleared first). `inBlockComment`: the line starts inside `/* */`;
    // returns whether it ends inside one.
    bool scan(QStringView line, bool inBlockComment, std::vector<Span>& out) const;
    // Only the `/* */` state at the end of the line, for lines not shown.
    bool blockCommentAfter(QStringView line, bool inBlockComment) const;

private:
    int word(QStringView line, int i, std::vector<Span>& out) const;
    bool packedKeywords(QStringView letters, int start, std::vector<Span>& out) const;
    bool m350_;
    bool blockComments_;
    bool upperOnly_;
};

} // namespace m350::ui
