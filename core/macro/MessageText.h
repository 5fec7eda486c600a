#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace m350::macro {

// #1510-#1513 fill the %.0f / %.3f placeholders of #1503 and #1505 texts, in order.
inline constexpr int kMessageValueFirst = 1510;

// Formats a status-line or dialog text: `%.Nf` takes the next value, `%%` is a literal %.
// Anything else is copied as written, so a stray % never garbles the message.
std::string formatMessageText(std::string_view text, const double (&values)[4]);

// A macro alarm's text (#3000) with `{#n}` fields: each is replaced by variable n's value, at
// most 3 decimals without trailing zeros ("0.62", "1", "vacant" for an empty variable). A simulator
// extra, so an alarm can say what a macro measured; `read` gives a variable's value.
std::string expandVariableFields(std::string_view text, const std::function<std::optional<double>(int)>& read);

} // namespace m350::macro
