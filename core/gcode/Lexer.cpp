#include "core/gcode/Lexer.h"

#include "core/gcode/DecimalScan.h"
#include "core/gcode/LexerText.h"

#include <array>
#include <charconv>

namespace m350::gcode {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// The general conversion, for numbers scanDecimal leaves alone.
bool parseNumber(std::string_view digits, double& value) {
    if (!digits.empty() && digits.back() == '.') {
        digits.remove_suffix(1); // `1.` is FANUC's 1.0
    }
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return !digits.empty() && ec == std::errc() && ptr == digits.data() + digits.size();
}

// The letters of one run (`G`, `GOTO`, `LEABS`; on FANUC also `GO TO`), where each one stands.
struct LetterRun {
    static constexpr std::size_t kMaxLetters = 16; // longer runs are never keywords
    std::array<char, kMaxLetters> upper{};
    std::array<std::uint32_t, kMaxLetters> offset{};
    std::array<std::uint32_t, kMaxLetters> column{};
    std::size_t count = 0; // may exceed kMaxLetters
    bool lowerCase = false;
};

} // namespace

std::vector<Token> Lexer::tokenize(std::string_view line) const {
    std::vector<Token> tokens;
    tokenize(line, tokens);
    return tokens;
}

void Lexer::tokenize(std::string_view line, std::vector<Token>& tokens) const {
    BlockCommentState comment;
    tokenize(line, tokens, comment);
}

// One pass over the bytes. Columns count characters: every byte of ASCII is one, and a multi-byte
// UTF-8 character (possible only in comments and invalid tokens) counts once.
void Lexer::tokenize(std::string_view line, std::vector<Token>& tokens, BlockCommentState& comment) const {
    tokens.clear();
    comment.openedOnThisLine = false;
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
    auto closeBlockComment = [&] {
        while (i < size) {
            if (text[i] == '*' && at(i + 1) == '/') {
                i += 2;
                column += 2;
                return true;
            }
            step();
        }
        return false;
    };
    auto nextNonSpace = [&](std::size_t k) {
        while (k < size && isSpace(text[k])) {
            ++k;
        }
        return k;
    };
    if (comment.open && !closeBlockComment()) {
        emit(TokenKind::End, i, column);
        return;
    }
    comment.open = false;
    while (i < size) {
        const char ch = text[i];
        const std::size_t start = i;
        const std::uint32_t startColumn = column;
        if (isSpace(ch)) {
            ++i;
            ++column;
            continue;
        }
        if (isLetter(ch)) {
            LetterRun run;
            while (i < size) {
                char c = text[i];
                if (isLetter(c)) {
                    run.lowerCase |= c >= 'a';
                    if (run.count < LetterRun::kMaxLetters) {
                        run.upper[run.count] = upperCase(c);
                        run.offset[run.count] = static_cast<std::uint32_t>(i);
                        run.column[run.count] = column;
                    }
                    ++run.count;
                    ++i;
                    ++column;
                } else if (c == '2' && run.count == 5 && isLetter(at(i + 1)) &&
                           (std::string_view(run.upper.data(), 5) == "MBYTE" ||
                            std::string_view(run.upper.data(), 5) == "MDATA")) {
                    run.upper[run.count] = c; // the M350's MBYTE2DATA and MDATA2BYTE
                    run.offset[run.count] = static_cast<std::uint32_t>(i);
                    run.column[run.count] = column;
                    ++run.count;
                    ++i;
                    ++column;
                } else if (dialect_.spacesInsignificant && isSpace(c) && isLetter(at(nextNonSpace(i)))) {
                    std::size_t ahead = nextNonSpace(i);
                    column += static_cast<std::uint32_t>(ahead - i);
                    i = ahead;
                } else {
                    break;
                }
            }
            if (run.count == 1) {
                emit(TokenKind::Letter, start, startColumn).letter = run.upper[0];
                continue;
            }
            KeywordSplit split;
            if (run.count <= LetterRun::kMaxLetters) {
                split = splitKeywords(std::string_view(run.upper.data(), run.count));
            }
            if (split.count == 0) {
                emit(TokenKind::Invalid, start, startColumn).issue = TokenIssue::UnknownWord;
                continue;
            }
            const std::size_t end = i;
            std::size_t first = 0;
            for (std::size_t part = 0; part < split.count; ++part) {
                const std::size_t last = first + split.length[part] - 1;
                const bool whole = split.count == 1; // keeps the spaces of `GO TO` in its length
                i = whole ? end : run.offset[last] + 1;
                Token& t = emit(TokenKind::Keyword, run.offset[first], run.column[first]);
                t.keyword = split.keyword[part];
                bool lowerCase = false;
                for (std::size_t k = first; k <= last; ++k) {
                    lowerCase |= text[run.offset[k]] >= 'a';
                }
                if (dialect_.upperCaseKeywords && lowerCase) {
                    t.issue = TokenIssue::LowerCaseKeyword;
                }
                first = last + 1;
            }
            i = end;
            continue;
        }
        const bool spacedPoint = dialect_.spacesInsignificant && ch == '.' && isDigit(at(nextNonSpace(i + 1)));
        if (isDigit(ch) || (ch == '.' && isDigit(at(i + 1))) || spacedPoint) {
            double value = 0.0;
            bool converted = scanDecimal(text, size, i, value);
            std::string packed; // FANUC: `1 0 . 5` is 10.5
            for (std::size_t k = nextNonSpace(i); dialect_.spacesInsignificant && k > i &&
                                                  (isDigit(at(k)) || at(k) == '.');
                 k = nextNonSpace(i)) {
                if (packed.empty()) {
                    packed.assign(text + start, i - start);
                }
                for (i = k; i < size && (isDigit(text[i]) || text[i] == '.'); ++i) {
                    packed.push_back(text[i]);
                }
            }
            if (!packed.empty()) {
                std::size_t k = 0;
                converted = scanDecimal(packed.data(), packed.size(), k, value);
            }
            column += static_cast<std::uint32_t>(i - start);
            Token& t = emit(TokenKind::Number, start, startColumn);
            if (converted) {
                t.number = value;
            } else if (!parseNumber(packed.empty() ? line.substr(start, i - start) : std::string_view(packed),
                                    t.number)) {
                t.kind = TokenKind::Invalid;
                t.issue = TokenIssue::MalformedNumber;
            }
            continue;
        }
        if ((ch == '/' && at(i + 1) == '/' && dialect_.slashSlashComments) || ch == ';') {
            break; // comment (M350) or end of block (FANUC) up to the end of the line
        }
        if (ch == '/' && at(i + 1) == '*' && dialect_.blockComments) {
            i += 2;
            column += 2;
            if (!closeBlockComment()) {
                comment = {true, true, startColumn};
                break;
            }
            continue;
        }
        if (ch == '*' && at(i + 1) == '/' && dialect_.blockComments) {
            i += 2;
            column += 2;
            emit(TokenKind::Invalid, start, startColumn).issue = TokenIssue::StrayCommentEnd;
            continue;
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
        case '.':
            if (dialect_.dotAfterComment && !tokens.empty() && tokens.back().kind == TokenKind::Comment) {
                single(TokenKind::Comment); // `(Relay test, press any key to exit).`
                tokens.back().issue = TokenIssue::StrayDot;
                continue;
            }
            break;
        default: break;
        }
        step();
        Token& t = emit(TokenKind::Invalid, start, startColumn);
        t.issue = fullWidthAscii(line.substr(start, i - start)) ? TokenIssue::FullWidth
                                                                 : TokenIssue::UnexpectedCharacter;
    }
    emit(TokenKind::End, i, column);
}

std::string Lexer::issueMessage(const Token& token, std::string_view line) const {
    const Message words = issueWords(token, line);
    return words.id.empty() ? std::string() : words.english();
}

Message Lexer::issueWords(const Token& token, std::string_view line) const {
    std::string text(tokenSource(token, line));
    switch (token.issue) {
    case TokenIssue::None: return {};
    case TokenIssue::UnknownWord: return message("lex_unknown_word", {text});
    case TokenIssue::MalformedNumber: return message("lex_malformed_number", {text});
    case TokenIssue::UnclosedComment: return message("lex_unclosed_comment");
    case TokenIssue::StrayCommentEnd: return message("lex_stray_comment_end");
    case TokenIssue::FullWidth: return message("lex_full_width", {text, fullWidthAscii(text)});
    case TokenIssue::UnexpectedCharacter: return message("lex_unexpected_character", {text});
    case TokenIssue::LowerCaseKeyword: {
        std::string upperText;
        for (char ch : text) {
            if (isLetter(ch)) {
                upperText.push_back(upperCase(ch));
            }
        }
        return message("lex_lower_case_keyword", {std::string(dialect_.name), upperText, text});
    }
    case TokenIssue::StrayDot: return message("lex_stray_dot");
    }
    return {};
}

} // namespace m350::gcode
