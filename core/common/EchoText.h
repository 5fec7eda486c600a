#pragma once

#include <cstddef>
#include <string>

namespace m350 {

// The most bytes of a program's own text (a comment shown by #3006, a token a diagnostic quotes, a
// dialog's prompt) that a message repeats: a line of a megabyte must not make every message a megabyte.
inline constexpr std::size_t kEchoLimit = 512;

// `text` cut to `limit` bytes at a UTF-8 character boundary, ending in "… (N more bytes)" when cut.
std::string clipEcho(std::string text, std::size_t limit = kEchoLimit);

} // namespace m350
