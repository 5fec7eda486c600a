#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace m350::files {

// Where and why a TOML text is refused before toml++ reads it.
struct TomlRefusal {
    int line = 1;
    int column = 1; // in code points, as toml++ counts
    std::string message;
};

// toml++ 3.3.0 asks whether a character is Unicode whitespace wherever it skips whitespace or reads
// a bare value (a number, date, boolean or anything not quoted, up to whitespace , ] } or #), and
// after a backslash in a """string""" and at the start of the line a line-ending backslash continues.
// For much of U+00A1-U+0499, U+2C6E-U+3067 and U+FB26-U+FEFE (Latin-1 signs, Cyrillic, CJK
// punctuation such as 。「」, presentation forms) that test reaches __builtin_unreachable: undefined
// behaviour, which UBSan stops at. Inside strings and comments toml++ only asks ASCII questions. So a
// text is refused where a non-ASCII character stands outside a string or comment (TOML allows none
// there; a byte-order mark opening the text excepted), a quote inside a bare value counting as no
// string, or at one of those two places of a """string""". Returns nothing for a text toml++ may read.
std::optional<TomlRefusal> findCharacterTomlCannotRead(std::string_view text);

} // namespace m350::files
