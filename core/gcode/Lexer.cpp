#include "core/gcode/Lexer.h"

#include "core/gcode/DecimalScan.h"

#include <charconv>
#include <optional>

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
char upper(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

// Keywords are at most 5 letters; longer runs are never keywords.
std::optional<Keyword> keywordFor(std::string_view upperWord) {
    for (int k = 0; k <= static_cast<int>(Keyword::Bcd); ++k) {
        if (upperWord == keywordSpelling(static_cast<Keyword>(k))) {
            return static_cast<Keyword>(k);
        }
    }
    return std::nullopt;
}

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

// Plain decimals, the bulk of every program, in one pass: when the digits form an integer below
// 2^53 and there are at most 22 after the point, mantissa / 10^k is one correctly rounded
// division, so the result equals what from_chars gives (Clinger's fast path).
// The general conversion, for numbers scanDecimal leaves alone.
bool parseNumber(std::string_view digits, double& value) {
    if (digits.back() == '.') {
        digits.remove_suffix(1); // `1.` is FANUC's 1.0
    }
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && ptr == digits.data() + digits.size();
}

} // namespace

std::vector<Token> Lexer::tokenize(std::string_view line) const {
    std::vector<Token> tokens;
    tokenize(line, tokens);
    return tokens;
}

// One pass over the bytes. Columns count characters: every byte of ASCII is one, and a multi-byte
// UTF-8 character (possible only in comments and invalid tokens) counts once.
void Lexer::tokenize(std::string_view line, std::vector<Token>& tokens) const {
    tokens.clear();
    const char* text = line.data();
    const std::size_t size = line.size();
    std::size_t i = 0;
    std::uint32_t column = 1;
    auto at = [&](std::size_t k) { return k < size ? text[k] : '\0'; };
    auto emit = [&](TokenKind kind, std::size_t start, std::uint32_t startColumn) -> Token& {
        Token& t = tokens.emplace_back();
        t.kind = kind;
        t.column = startColumn;
        t.offset = static_cast<std::uint32_t>(start);
        t.length = static_cast<std::uint32_t>(i - start);
        return t;
    };
    // Advances over one character, which may be several bytes long.
    auto step = [&] {
        ++i;
        while (i < size && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) {
            ++i;
        }
        ++column;
    };
    while (i < size) {
        const char ch = text[i];
        const std::size_t start = i;
        const std::uint32_t startColumn = column;
        if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n') {
            ++i;
            ++column;
            continue;
        }
        if (isLetter(ch)) {
            char word[8];
            std::size_t letters = 0;
            bool lowerCase = false;
            while (i < size) {
                char c = text[i];
                if (isLetter(c)) {
                    lowerCase |= c >= 'a';
                    if (letters < sizeof word) {
                        word[letters] = upper(c);
                    }
                    ++letters;
                    ++i;
                    ++column;
                } else if (dialect_.spacesInsignificant && isSpace(c)) {
                    std::size_t ahead = i + 1;
                    while (isSpace(at(ahead))) {
                        ++ahead;
                    }
                    if (!isLetter(at(ahead))) {
                        break;
                    }
                    column += static_cast<std::uint32_t>(ahead - i);
                    i = ahead;
                } else {
                    break;
                }
            }
            if (letters == 1) {
                emit(TokenKind::Letter, start, startColumn).letter = word[0];
                continue;
            }
            auto keyword = letters <= sizeof word ? keywordFor(std::string_view(word, letters)) : std::nullopt;
            if (!keyword) {
                emit(TokenKind::Invalid, start, startColumn).issue = TokenIssue::UnknownWord;
                continue;
            }
            Token& t = emit(TokenKind::Keyword, start, startColumn);
            t.keyword = *keyword;
            if (dialect_.upperCaseKeywords && lowerCase) {
                t.issue = TokenIssue::LowerCaseKeyword;
            }
            continue;
        }
        if (isDigit(ch) || (ch == '.' && isDigit(at(i + 1)))) {
            double value = 0.0;
            bool converted = scanDecimal(text, size, i, value);
            column += static_cast<std::uint32_t>(i - start);
            Token& t = emit(TokenKind::Number, start, startColumn);
            if (converted) {
                t.number = value;
            } else if (!parseNumber(line.substr(start, i - start), t.number)) {
                t.kind = TokenKind::Invalid;
                t.issue = TokenIssue::MalformedNumber;
            }
            continue;
        }
        if ((ch == '/' && at(i + 1) == '/' && dialect_.slashSlashComments) || ch == ';') {
            break; // comment (M350) or end of block (FANUC) up to the end of the line
        }
        if (ch == '(') {
            while (i < size && text[i] != ')') {
                step();
            }
            if (i >= size) {
                emit(TokenKind::Invalid, start, startColumn).issue = TokenIssue::UnclosedComment;
                break;
            }
            step();
            emit(TokenKind::Comment, start, startColumn);
            continue;
        }
        auto single = [&](TokenKind kind) {
            ++i;
            ++column;
            emit(kind, start, startColumn);
        };
        auto compare = [&](BinaryOp op, std::size_t length) {
            i += length;
            column += static_cast<std::uint32_t>(length);
            emit(TokenKind::Compare, start, startColumn).compare = op;
        };
        switch (ch) {
        case '#': single(TokenKind::Hash); continue;
        case '[': single(TokenKind::LBracket); continue;
        case ']': single(TokenKind::RBracket); continue;
        case '+': single(TokenKind::Plus); continue;
        case '-': single(TokenKind::Minus); continue;
        case '*': single(TokenKind::Star); continue;
        case '/': single(TokenKind::Slash); continue;
        case ',': single(TokenKind::Comma); continue;
        case '%': single(TokenKind::Percent); continue;
        case '=': at(i + 1) == '=' ? compare(BinaryOp::Eq, 2) : single(TokenKind::Assign); continue;
        case '<': at(i + 1) == '=' ? compare(BinaryOp::Le, 2) : compare(BinaryOp::Lt, 1); continue;
        case '>': at(i + 1) == '=' ? compare(BinaryOp::Ge, 2) : compare(BinaryOp::Gt, 1); continue;
        case '!':
            if (at(i + 1) == '=') {
                compare(BinaryOp::Ne, 2);
                continue;
            }
            break;
        default: break;
        }
        step();
        Token& t = emit(TokenKind::Invalid, start, startColumn);
        t.issue = asciiFor(line.substr(start, i - start)) ? TokenIssue::FullWidth : TokenIssue::UnexpectedCharacter;
    }
    emit(TokenKind::End, i, column);
}

std::string Lexer::issueMessage(const Token& token, std::string_view line) const {
    std::string text(tokenSource(token, line));
    switch (token.issue) {
    case TokenIssue::None: return {};
    case TokenIssue::UnknownWord: return "unknown word '" + text + "'";
    case TokenIssue::MalformedNumber: return "malformed number '" + text + "'";
    case TokenIssue::UnclosedComment: return "comment '(' is not closed with ')'";
    case TokenIssue::FullWidth:
        return "full-width '" + text + "' is not G-code (did you mean '" + asciiFor(text) + "'?)";
    case TokenIssue::UnexpectedCharacter: return "unexpected character '" + text + "'";
    case TokenIssue::LowerCaseKeyword: {
        std::string upperText;
        for (char ch : text) {
            if (isLetter(ch)) {
                upperText.push_back(upper(ch));
            }
        }
        return "keywords are upper case in the " + std::string(dialect_.name) + " dialect: write " + upperText +
               ", not " + text;
    }
    }
    return {};
}

} // namespace m350::gcode
