#pragma once

#include "core/gcode/Expression.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace m350::gcode {

enum class TokenKind : std::uint8_t {
    Number, Letter, Keyword, Hash, LBracket, RBracket, Plus, Minus, Star, Slash, Comma,
    Assign, Compare, Comment, Percent, Invalid, End
};

enum class Keyword : std::uint8_t {
    If, Goto, Then, While, Do, End,
    Eq, Ne, Lt, Gt, Le, Ge, And, Or, Xor, Mod,
    Popen, Pclos, Dprnt, Bprnt,                  // FANUC external output
    MSetData, MGetData, MByte2Data, MData2Byte,  // M350 Modbus
    Abs, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Round, Fix, Fup, Ln, Exp, Bin, Bcd
};

// Why a token cannot be used; the message is built from it only when an error is reported.
// StrayDot is only a note: the token is ignored and the line still runs.
enum class TokenIssue : std::uint8_t {
    None, UnknownWord, MalformedNumber, UnclosedComment, StrayCommentEnd, FullWidth, UnexpectedCharacter,
    LowerCaseKeyword, StrayDot
};

inline bool isNote(TokenIssue issue) {
    return issue == TokenIssue::StrayDot;
}

// A token refers to its text by position in the line, so lexing a line allocates nothing.
struct Token {
    TokenKind kind = TokenKind::End;
    TokenIssue issue = TokenIssue::None;
    char letter = 0;
    Keyword keyword = Keyword::If;
    BinaryOp compare = BinaryOp::Eq;
    std::uint32_t column = 0; // 1-based, in characters
    std::uint32_t offset = 0; // byte offset in the line
    std::uint32_t length = 0; // bytes
    double number = 0.0;
};

bool isFunctionKeyword(Keyword k);
Function functionOf(Keyword k);
const char* keywordSpelling(Keyword k);

// The token's characters as written.
std::string_view tokenSource(const Token& token, std::string_view line);
// A comment token's text, without its parentheses.
std::string_view commentText(const Token& token, std::string_view line);

} // namespace m350::gcode
