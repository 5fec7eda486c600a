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
    auto digit = [](char c) { return static_cast<unsigned>(c - '0') < 10u; };
    const std::size_t start = i;
    std::uint64_t mantissa = 0;
    while (i < size && digit(text[i])) {
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
        ++i;
    }
    std::size_t fraction = 0;
    const bool point = i < size && text[i] == '.';
    if (point) {
        const std::size_t point = ++i;
        while (i < size && digit(text[i])) {
            mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
            ++i;
        }
        fraction = i - point;
        if (i < size && text[i] == '.') { // 1.2.3: take the rest of the token, then refuse it
            while (i < size && (digit(text[i]) || text[i] == '.')) {
                ++i;
            }
            return false;
        }
    }
    const std::size_t digits = i - start - (point ? 1 : 0);
    if (digits > 15) {
        // Leading zeros do not count, but more than 15 significant digits may not fit 2^53.
        std::size_t significant = digits;
        for (std::size_t k = start; k < i && (text[k] == '0' || text[k] == '.'); ++k) {
            significant -= text[k] == '0' ? 1 : 0;
        }
        if (significant > 15) {
            return false;
        }
    }
    if (fraction > 22) {
        return false;
    }
    value = static_cast<double>(mantissa);
    if (fraction != 0) {
        value /= kPowersOfTen[fraction];
    }
    return true;
}

} // namespace m350::gcode
