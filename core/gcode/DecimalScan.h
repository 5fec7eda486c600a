#pragma once

#include <cstddef>
#include <cstdint>

namespace m350::gcode {

// Scans the digits and points of a number starting at text[i] (advancing i past them) and converts
// plain decimals on the way: when the digits form an integer below 2^53 (at most 15 significant
// digits) with at most 22 after one point, mantissa / 10^k is a single correctly rounded division
// and equals what from_chars gives (Clinger's fast path). Returns false when the number needs the
// general conversion (or is malformed, like 1.2.3); i is then still past the digits and points.
inline bool scanDecimal(const char* text, std::size_t size, std::size_t& i, double& value) {
    static constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                              1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    std::uint64_t mantissa = 0;
    int fraction = -1; // digits after the point; -1 before it
    int significant = 0;
    bool plain = true;
    for (; i < size; ++i) {
        char c = text[i];
        if (c >= '0' && c <= '9') {
            mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
            significant += mantissa != 0 ? 1 : 0;
            fraction += fraction >= 0 ? 1 : 0;
            plain &= significant <= 15;
        } else if (c == '.') {
            plain &= fraction < 0;
            fraction = 0;
        } else {
            break;
        }
    }
    int scale = fraction < 0 ? 0 : fraction;
    if (!plain || scale > 22) {
        return false;
    }
    value = static_cast<double>(mantissa) / kPowersOfTen[scale];
    return true;
}

} // namespace m350::gcode
