#pragma once

#include "core/gcode/LineFindings.h"
#include "core/gcode/LineTokens.h"

#include <cstddef>
#include <string>

namespace m350::gcode {

// A ']' where none can stand, at `at` in `context` ("IF condition", "this expression" ...): the
// line fails, and the message shows the #[...] its author most likely meant when a '#' before it
// reads as the start of an indirect reference written without its '['.
[[noreturn]] void failStrayBracket(const LineTokens& tokens, LineFindings& findings, const Token& at, const char* context);

// For `#1552+#20-1]`: `#[1552+#20-1]`, from the text between the '#' at `hashToken` and the first
// ']' after it (before `strayToken`); empty when the reference is written #[...] already.
std::string hashBracketHint(const LineTokens& tokens, std::size_t hashToken, std::size_t strayToken);

} // namespace m350::gcode
