#pragma once

#include "core/macro/Value.h"

#include <optional>
#include <string>

namespace m350::macro {

// DPRNT's decimal form of one variable, `#v[cd]`, as a FANUC sends it with parameter PRT (6001#1)
// = 0: a sign position (a space for a value that is not negative, '-' otherwise), then exactly c
// integer digits whose high-order zeros go out as spaces (the units digit always as a digit), then,
// when d > 0, the point and d digits rounded half away from zero (d = 0: no point). Digits above
// the c-th are not sent. <vacant> goes out as 0.
std::string formatDprnt(Value value, int integerDigits, int fractionDigits);

// BPRNT's binary form of `#v[c]`: the value times 10^c, rounded, as a 32-bit two's complement
// integer, most significant byte first; <vacant> is 0. Nothing when it does not fit in 32 bits.
std::optional<std::string> formatBprnt(Value value, int fractionDigits);

} // namespace m350::macro
