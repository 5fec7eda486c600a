#pragma once

#include <cstddef>
#include <cstdint>

namespace m350::gcode {

namespace decimal {

// mantissa / 10^fraction as a double, when that is a single correctly rounded division and so
// equals what from_chars gives (Clinger's fast path): the digits [start, end) (the point among
// them) form an integer below 2^53 (at most 15 significant digits), with at most 22 after the point.
inline bool convertExactly(const char* start, const char* end, std::size_t digits, std::size_t fraction,
                           std::uint64_t mantissa, double& value) {
    static constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                              1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    if (digits > 15) {
        // Leading zeros do not count, but more than 15 significant digits may not fit 2^53.
        std::size_t significant = digits;
        for (const char* k = start; k < end && (*k == '0' || *k == '.'); ++k) {
            significant -= *k == '0' ? 1 : 0;
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

inline unsigned digitValue(char c) {
    return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
}

} // namespace decimal

// Scans the digits and points of a number starting at text[i] (advancing i past them) and converts
// plain decimals on the way (decimal::convertExactly says which). Returns false when the number
// needs the general conversion (or is malformed, like 1.2.3); i is then still past the digits and
// points.
inline bool scanDecimal(const char* text, std::size_t size, std::size_t& i, double& value) {
    auto digit = [](char c) { return decimal::digitValue(c) < 10u; };
    const std::size_t start = i;
    std::uint64_t mantissa = 0;
    while (i < size && digit(text[i])) {
        mantissa = mantissa * 10 + decimal::digitValue(text[i]);
        ++i;
    }
    std::size_t fraction = 0;
    const bool point = i < size && text[i] == '.';
    if (point) {
        const std::size_t point = ++i;
        while (i < size && digit(text[i])) {
            mantissa = mantissa * 10 + decimal::digitValue(text[i]);
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
    return decimal::convertExactly(text + start, text + i, digits, fraction, mantissa, value);
}

// The same conversion for text known to end in a character that is neither a digit nor a point
// (the plain-line parser's lines end in a line end), so no bounds are tested. Returns where the
// number ends, or nullptr when it needs the general conversion, is malformed or has no digit.
inline const char* scanTerminatedDecimal(const char* const text, double& value) {
    static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    // Pointers kept in locals, and read as unsigned char: a char read may alias a pointer in memory.
    const auto* const start = reinterpret_cast<const unsigned char*>(text);
    const unsigned char* at = start;
    std::uint64_t mantissa = 0;
    // Two digits a step: the byte after a digit is always there (the text ends in a non-digit).
    auto digitsInto = [&mantissa](const unsigned char* from) {
        while (true) {
            const unsigned first = from[0] - 48u;
            if (first > 9u) {
                return from;
            }
            const unsigned second = from[1] - 48u;
            if (second > 9u) {
                mantissa = mantissa * 10 + first;
                return from + 1;
            }
            mantissa = mantissa * 100 + (first * 10 + second);
            from += 2;
        }
    };
    at = digitsInto(at);
    std::size_t digits = static_cast<std::size_t>(at - start);
    std::size_t fraction = 0;
    if (*at == '.') {
        const unsigned char* const point = ++at;
        at = digitsInto(at);
        if (*at == '.') {
            return nullptr;
        }
        fraction = static_cast<std::size_t>(at - point);
        digits += fraction;
    }
    const char* const end = reinterpret_cast<const char*>(at);
    if (digits - 1 < 15) [[likely]] {
        // 1 to 15 digits: convertExactly's case without its tests (dividing by 1 is exact). The
        // mantissa is below 10^15, so it converts as a signed number (one instruction).
        value = static_cast<double>(static_cast<std::int64_t>(mantissa)) / kPowersOfTen[fraction];
        return end;
    }
    return digits != 0 && decimal::convertExactly(text, end, digits, fraction, mantissa, value) ? end : nullptr;
}

} // namespace m350::gcode
