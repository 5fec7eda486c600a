#include "core/gcode/Lexer.h"

#include <cctype>
#include <charconv>
#include <optional>
#include <string>

namespace m350::gcode {

namespace {

bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::optional<Keyword> keywordFor(std::string_view word) {
    for (int k = 0; k <= static_cast<int>(Keyword::Bcd); ++k) {
        if (word == keywordSpelling(static_cast<Keyword>(k))) {
            return static_cast<Keyword>(k);
        }
    }
    return std::nullopt;
}

// Walks a line byte by byte while counting characters, so columns match what an editor shows.
class Cursor {
public:
    explicit Cursor(std::string_view line) : line_(line) {}
    bool done() const { return pos_ >= line_.size(); }
    char peek(std::size_t ahead = 0) const { return pos_ + ahead < line_.size() ? line_[pos_ + ahead] : '\0'; }
    std::uint32_t column() const { return column_; }
    std::uint32_t offset() const { return static_cast<std::uint32_t>(pos_); }
    void advance() {
        ++pos_;
        while (pos_ < line_.size() && (static_cast<unsigned char>(line_[pos_]) & 0xC0) == 0x80) {
            ++pos_; // continuation bytes of one character
        }
        ++column_;
    }
    std::string_view from(std::uint32_t start) const { return line_.substr(start, pos_ - start); }

private:
    std::string_view line_;
    std::size_t pos_ = 0;
    std::uint32_t column_ = 1;
};

// Full-width punctuation typed with a Chinese input method looks right but is not G-code.
const char* asciiFor(std::string_view character) {
    static constexpr std::pair<std::string_view, const char*> table[] = {
        {"（", "("}, {"）", ")"}, {"［", "["}, {"］", "]"}, {"＃", "#"}, {"，", ","}, {"＝", "="},
        {"＋", "+"}, {"－", "-"}, {"＊", "*"}, {"／", "/"}, {"；", ";"}, {"　", " "}, {"＜", "<"}, {"＞", ">"}};
    for (auto [wide, ascii] : table) {
        if (character == wide) {
            return ascii;
        }
    }
    return nullptr;
}

} // namespace

std::vector<Token> Lexer::tokenize(std::string_view line) const {
    std::vector<Token> tokens;
    Cursor c(line);
    auto emit = [&](TokenKind kind, std::uint32_t column, std::uint32_t offset) -> Token& {
        Token t;
        t.kind = kind;
        t.column = column;
        t.offset = offset;
        t.length = c.offset() - offset;
        tokens.push_back(std::move(t));
        return tokens.back();
    };
    while (!c.done()) {
        char ch = c.peek();
        std::uint32_t column = c.column();
        std::uint32_t offset = c.offset();
        if (isSpace(ch)) {
            c.advance();
            continue;
        }
        if ((ch == '/' && c.peek(1) == '/' && dialect_.slashSlashComments) || ch == ';') {
            break; // comment (M350) or end of block (FANUC) up to the end of the line
        }
        if (ch == '(') {
            c.advance();
            std::uint32_t textStart = c.offset();
            while (!c.done() && c.peek() != ')') {
                c.advance();
            }
            std::string text(c.from(textStart));
            if (c.done()) {
                Token& t = emit(TokenKind::Invalid, column, offset);
                t.text = "comment '(' is not closed with ')'";
                break;
            }
            c.advance();
            emit(TokenKind::Comment, column, offset).text = std::move(text);
            continue;
        }
        if (isLetter(ch)) {
            std::string word;
            while (!c.done()) {
                if (isLetter(c.peek())) {
                    word.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c.peek()))));
                    c.advance();
                } else if (dialect_.spacesInsignificant && isSpace(c.peek())) {
                    std::size_t ahead = 1;
                    while (isSpace(c.peek(ahead))) {
                        ++ahead;
                    }
                    if (!isLetter(c.peek(ahead))) {
                        break;
                    }
                    while (isSpace(c.peek())) {
                        c.advance();
                    }
                } else {
                    break;
                }
            }
            if (word.size() == 1) {
                emit(TokenKind::Letter, column, offset).letter = word[0];
            } else if (auto k = keywordFor(word)) {
                std::string written(c.from(offset));
                Token& t = emit(TokenKind::Keyword, column, offset);
                t.keyword = *k;
                if (dialect_.upperCaseKeywords && written != word) {
                    t.problem = "keywords are upper case in the " + std::string(dialect_.name) + " dialect: write " +
                                word + ", not " + written;
                }
                t.text = std::move(written);
            } else {
                emit(TokenKind::Invalid, column, offset).text = "unknown word '" + std::string(c.from(offset)) + "'";
            }
            continue;
        }
        if (isDigit(ch) || (ch == '.' && isDigit(c.peek(1)))) {
            while (isDigit(c.peek()) || c.peek() == '.') {
                c.advance();
            }
            std::string_view digits = c.from(offset);
            Token& t = emit(TokenKind::Number, column, offset);
            std::string copy(digits);
            if (copy.back() == '.') {
                copy.pop_back(); // `1.` is FANUC's 1.0
            }
            auto [ptr, ec] = std::from_chars(copy.data(), copy.data() + copy.size(), t.number);
            if (ec != std::errc() || ptr != copy.data() + copy.size()) {
                t.kind = TokenKind::Invalid;
                t.text = "malformed number '" + std::string(digits) + "'";
            }
            continue;
        }
        auto two = [&](char second) { return c.peek(1) == second; };
        auto compare = [&](BinaryOp op, int length) {
            for (int i = 0; i < length; ++i) {
                c.advance();
            }
            Token& t = emit(TokenKind::Compare, column, offset);
            t.compare = op;
            t.text = std::string(c.from(offset));
        };
        switch (ch) {
        case '#': c.advance(); emit(TokenKind::Hash, column, offset); continue;
        case '[': c.advance(); emit(TokenKind::LBracket, column, offset); continue;
        case ']': c.advance(); emit(TokenKind::RBracket, column, offset); continue;
        case '+': c.advance(); emit(TokenKind::Plus, column, offset); continue;
        case '-': c.advance(); emit(TokenKind::Minus, column, offset); continue;
        case '*': c.advance(); emit(TokenKind::Star, column, offset); continue;
        case '/': c.advance(); emit(TokenKind::Slash, column, offset); continue;
        case ',': c.advance(); emit(TokenKind::Comma, column, offset); continue;
        case '%': c.advance(); emit(TokenKind::Percent, column, offset); continue;
        case '=':
            if (two('=')) {
                compare(BinaryOp::Eq, 2);
            } else {
                c.advance();
                emit(TokenKind::Assign, column, offset);
            }
            continue;
        case '!':
            if (two('=')) {
                compare(BinaryOp::Ne, 2);
                continue;
            }
            break;
        case '<': two('=') ? compare(BinaryOp::Le, 2) : compare(BinaryOp::Lt, 1); continue;
        case '>': two('=') ? compare(BinaryOp::Ge, 2) : compare(BinaryOp::Gt, 1); continue;
        default: break;
        }
        c.advance();
        std::string character(c.from(offset));
        Token& t = emit(TokenKind::Invalid, column, offset);
        if (const char* ascii = asciiFor(character)) {
            t.text = "full-width '" + character + "' is not G-code (did you mean '" + ascii + "'?)";
        } else {
            t.text = "unexpected character '" + character + "'";
        }
    }
    Token end;
    end.kind = TokenKind::End;
    end.column = c.column();
    end.offset = c.offset();
    tokens.push_back(end);
    return tokens;
}

} // namespace m350::gcode
