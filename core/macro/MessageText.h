#pragma once

#include <string>
#include <string_view>

namespace m350::macro {

// #1510-#1513 fill the %.0f / %.3f placeholders of #1503 and #1505 texts, in order.
inline constexpr int kMessageValueFirst = 1510;

// Formats a status-line or dialog text: `%.Nf` takes the next value, `%%` is a literal %.
// Anything else is copied as written, so a stray % never garbles the message.
std::string formatMessageText(std::string_view text, const double (&values)[4]);

} // namespace m350::macro
