#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace m350 {

// Converts a program value to an integer without undefined behaviour: out-of-range values
// saturate and NaN gives 0. Macros can hold any double (`#1300 = 1e20`); the integer it names
// must still be computable so the error can be reported.
inline std::int32_t saturatingInt(double v) {
    if (std::isnan(v)) {
        return 0;
    }
    if (v >= static_cast<double>(std::numeric_limits<std::int32_t>::max())) {
        return std::numeric_limits<std::int32_t>::max();
    }
    if (v <= static_cast<double>(std::numeric_limits<std::int32_t>::min())) {
        return std::numeric_limits<std::int32_t>::min();
    }
    return static_cast<std::int32_t>(v);
}

// Rounded half away from zero, as FANUC's ROUND, then saturated.
inline std::int32_t roundToInt(double v) {
    return saturatingInt(std::round(v));
}

// At the parameters' four decimals (params.toml's resolution for a real): a sum or difference of
// two of them written to a file reads -118.677, not -118.67699999999999.
inline double atFourDecimals(double v) {
    return std::round(v * 1e4) / 1e4;
}

} // namespace m350
