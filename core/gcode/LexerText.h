#pragma once

#include "core/gcode/Token.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace m350::gcode {

// The lexer's tables of words and characters.

inline bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
inline char upperCase(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

// A run of letters read as keywords: one (`GOTO`) or several packed ones (`LEABS`, `ANDFIX`).
struct KeywordSplit {
    static constexpr std::size_t kMaxParts = 8;
    std::array<Keyword, kMaxParts> keyword{};
    std::array<std::uint8_t, kMaxParts> length{};
    std::size_t count = 0; // 0: the run is not made of keywords
};

// `upperWord` is upper case. A whole keyword wins; otherwise the first split found, trying the
// longest keyword first at each point (no two keywords make another one, so the split is unique
// for every run that occurs in practice).
KeywordSplit splitKeywords(std::string_view upperWord);

// The ASCII character a full-width one typed with a Chinese input method stands for, or nullptr.
const char* fullWidthAscii(std::string_view character);

} // namespace m350::gcode
