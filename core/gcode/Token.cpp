#include "core/gcode/Token.h"

namespace m350::gcode {

bool isFunctionKeyword(Keyword k) {
    return k >= Keyword::Abs;
}

Function functionOf(Keyword k) {
    return static_cast<Function>(static_cast<int>(k) - static_cast<int>(Keyword::Abs));
}

const char* keywordSpelling(Keyword k) {
    static constexpr const char* spellings[] = {
        "IF", "GOTO", "THEN", "WHILE", "DO", "END", "EQ", "NE", "LT", "GT", "LE", "GE", "AND", "OR", "XOR", "MOD",
        "POPEN", "PCLOS", "DPRNT", "BPRNT", "MSETDATA", "MGETDATA", "MBYTE2DATA", "MDATA2BYTE",
        "ABS", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ROUND", "FIX", "FUP", "LN", "EXP", "BIN", "BCD"};
    return spellings[static_cast<int>(k)];
}

std::string_view tokenSource(const Token& token, std::string_view line) {
    return line.substr(token.offset, token.length);
}

std::string_view commentText(const Token& token, std::string_view line) {
    std::string_view text = tokenSource(token, line);
    if (!text.empty() && text.front() == '(') {
        text.remove_prefix(1);
    }
    if (!text.empty() && text.back() == ')') {
        text.remove_suffix(1);
    }
    return text;
}

} // namespace m350::gcode
