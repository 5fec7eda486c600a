#include "core/gcode/LineChecks.h"

#include "core/common/Numeric.h"

#include <cmath>
#include <string_view>
#include <utility>

namespace m350::gcode {

// A WHILE, DO or END line with a syntax error still opens or closes its loop, so the error is
// reported once and not again as an unpaired END. The program cannot run with it anyway.
std::optional<Block> LineChecks::brokenLoopBlock(Block block) const {
    std::size_t first = 0;
    while (first < tokens_.size() && (tokens_[first].kind == TokenKind::Comment ||
                                      tokens_[first].kind == TokenKind::Letter ||
                                      tokens_[first].kind == TokenKind::Number)) {
        ++first; // N label
    }
    if (first >= tokens_.size() || tokens_[first].kind != TokenKind::Keyword ||
        (tokens_[first].keyword != Keyword::While && tokens_[first].keyword != Keyword::End &&
         tokens_[first].keyword != Keyword::Do)) {
        return std::nullopt;
    }
    bool isWhile = tokens_[first].keyword == Keyword::While;
    block.control = tokens_[first].keyword == Keyword::End ? Control::End : Control::While;
    block.controlColumn = tokens_[first].column;
    block.words = {};
    block.assignments = {};
    block.loopId = kUnknownLoop; // the parser then trusts no pairing in this program
    for (std::size_t i = first; i + 1 < tokens_.size(); ++i) {
        bool marker = isWhile ? (tokens_[i].kind == TokenKind::Keyword && tokens_[i].keyword == Keyword::Do)
                              : i == first;
        if (marker && tokens_[i + 1].kind == TokenKind::Number) {
            block.loopId = saturatingInt(tokens_[i + 1].number);
            break;
        }
    }
    return block;
}

// `#1=1E308`, `G4 P1E3`: G-code has no exponent notation, and FANUC refuses it too. Read as a
// number and an E word, the E would be silently ignored. On FANUC, a G65 line's `A1E2` is A and
// the argument E (#8), as FANUC reads it; so is a line of a code that calls a macro
// (Dialect::argumentCodes). A variable's number is never a mantissa: `Y#32E2.` is
// the words Y#32 and E2. in both dialects (a probing package's `G65P9730...Y#32E2.`).
void LineChecks::checkExponents() const {
    auto adjacent = [this](std::size_t a, std::size_t b) {
        return tokens_[a].offset + tokens_[a].length == tokens_[b].offset;
    };
    auto passesArguments = [this](const Token& letter, const Token& number) {
        if (letter.kind != TokenKind::Letter || number.kind != TokenKind::Number) {
            return false;
        }
        if (letter.letter == 'G' && number.number == 65) {
            return true;
        }
        for (auto [codeLetter, code] : dialect_.argumentCodes) {
            if (letter.letter == codeLetter && number.number == code) {
                return true;
            }
        }
        return false;
    };
    bool eArgument = false;
    if (dialect_.callArgument('E')) {
        for (std::size_t i = 0; i + 1 < tokens_.size(); ++i) {
            eArgument |= passesArguments(tokens_[i], tokens_[i + 1]);
        }
    }
    for (std::size_t i = 0; i + 2 < tokens_.size(); ++i) {
        if (tokens_[i].kind == TokenKind::Keyword &&
            (tokens_[i].keyword == Keyword::Dprnt || tokens_[i].keyword == Keyword::Bprnt)) {
            break; // DPRNT text (`DPRNT[1E5]`) is no number
        }
        const Token& e = tokens_[i + 1];
        if (tokens_[i].kind != TokenKind::Number || e.kind != TokenKind::Letter || e.letter != 'E' ||
            !adjacent(i, i + 1)) {
            continue;
        }
        std::size_t exponent = i + 2;
        if ((tokens_[exponent].kind == TokenKind::Plus || tokens_[exponent].kind == TokenKind::Minus) &&
            adjacent(i + 1, exponent)) {
            ++exponent;
        }
        if (tokens_[exponent].kind != TokenKind::Number || !adjacent(exponent - 1, exponent)) {
            continue;
        }
        if (i > 0 && tokens_[i - 1].kind == TokenKind::Hash) {
            continue;
        }
        if (eArgument && i > 0 && tokens_[i - 1].kind == TokenKind::Letter) {
            continue;
        }
        const Token& end = tokens_[exponent];
        std::string written(tokens_.line().substr(tokens_[i].offset, end.offset + end.length - tokens_[i].offset));
        findings_.fail(tokens_[i], message("parse_exponent", {written}));
    }
}

// `X[#1330+#1300-1]` adds a pocket coordinate to a tool number: never what anyone means, and exactly
// what the M350 manual's damaged listing reads. The author wanted `X#[1330+#1300-1]`.
void LineChecks::lintTableArithmetic(const Word& word, std::size_t firstToken, std::size_t endToken) const {
    if (word.isNumber() || pool_[word.value].kind != ExprKind::Binary || dialect_.indexedTables.empty()) {
        return;
    }
    ExprId leftmost = word.value;
    while (pool_[leftmost].kind == ExprKind::Binary) {
        leftmost = pool_[leftmost].lhs;
    }
    const ExprNode& base = pool_[leftmost];
    if (base.kind != ExprKind::Variable || base.lhs != kNoExpr) {
        return;
    }
    for (const IndexedTable& table : dialect_.indexedTables) {
        if (base.number == table.base) {
            std::uint32_t from = tokens_[firstToken].offset;
            std::uint32_t to = tokens_[endToken - 1].offset + tokens_[endToken - 1].length;
            std::string written(tokens_.line().substr(from, to - from));
            std::string meant = written;
            if (auto at = meant.find("[#"); at != std::string::npos) {
                meant.replace(at, 2, "#[");
            } else if (meant.size() > 2 && meant[1] == '#') { // unbracketed (m350): `X#1330+#1300-1`
                meant = meant.substr(0, 2) + "[" + meant.substr(2) + "]";
            }
            std::string b = std::to_string(table.base);
            findings_.lint(word.column, message("lint_table_added", {written, b, bilingual(table.what, table.chinese), meant}));
            return;
        }
    }
}

// `(rough (T1) pass)`: comments do not nest, on the M350 ("nested parentheses inside comments
// fail", community test reports) as on FANUC. The comment ends at the first ')' and `pass)` is read
// as words; said at the inner '(' so the alarm that follows makes sense.
void LineChecks::lintNestedComments() const {
    for (const Token& t : tokens_) {
        if (t.kind != TokenKind::Comment || t.length < 2 || tokens_.line()[t.offset] != '(') {
            continue;
        }
        std::uint32_t column = t.column + 1;
        for (std::uint32_t i = t.offset + 1; i + 1 < t.offset + t.length; ++i) {
            const auto byte = static_cast<unsigned char>(tokens_.line()[i]);
            if (byte == '(') {
                findings_.note(column, message("lint_comment_nested"));
                break;
            }
            column += (byte & 0xC0) != 0x80 ? 1 : 0; // one per character, not per UTF-8 byte
        }
    }
}

} // namespace m350::gcode
