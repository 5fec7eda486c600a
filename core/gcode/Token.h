#pragma once

#include "core/gcode/Expression.h"

#include <cstdint>
#include <string>

namespace m350::gcode {

enum class TokenKind : std::uint8_t {
    Number, Letter, Keyword, Hash, LBracket, RBracket, Plus, Minus, Star, Slash, Comma,
    Assign, Compare, Comment, Percent, Invalid, End
};

enum class Keyword : std::uint8_t {
    If, Goto, Then, While, Do, End,
    Eq, Ne, Lt, Gt, Le, Ge, And, Or, Xor, Mod,
    Abs, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Round, Fix, Fup, Ln, Exp, Bin, Bcd
};

struct Token {
    TokenKind kind = TokenKind::End;
    std::uint32_t column = 0;    // 1-based, in characters
    std::uint32_t offset = 0;    // byte offset in the line
    std::uint32_t length = 0;    // bytes
    double number = 0.0;
    char letter = 0;
    Keyword keyword = Keyword::If;
    BinaryOp compare = BinaryOp::Eq;
    std::string text; // comment text, or the characters of an Invalid token / unknown word
    std::string problem; // a valid token written in a way the dialect refuses (`while` on the M350)
};

bool isFunctionKeyword(Keyword k);
Function functionOf(Keyword k);
const char* keywordSpelling(Keyword k);

} // namespace m350::gcode
