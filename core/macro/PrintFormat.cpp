#include "core/macro/PrintFormat.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace m350::macro {

std::string formatDprnt(Value value, int integerDigits, int fractionDigits) {
    const double v = value.vacant ? 0.0 : value.number;
    const double scale = std::pow(10.0, fractionDigits);
    double units = std::round(std::abs(v) * scale); // in 10^-d, half away from zero
    if (!std::isfinite(units)) {
        units = 0.0;
    }
    const double whole = std::floor(units / scale);
    const double fraction = units - whole * scale;
    std::string out(1, v < 0 && units > 0 ? '-' : ' ');
    const double kept = std::fmod(whole, std::pow(10.0, integerDigits)); // the digits that go out
    bool leading = true;
    for (int k = integerDigits - 1; k >= 0; --k) {
        const int digit = static_cast<int>(std::fmod(std::floor(kept / std::pow(10.0, k)), 10.0));
        leading = leading && digit == 0 && k > 0;
        out += leading ? ' ' : static_cast<char>('0' + digit);
    }
    if (fractionDigits > 0) {
        out += '.';
        for (int k = fractionDigits - 1; k >= 0; --k) {
            out += static_cast<char>('0' + static_cast<int>(std::fmod(std::floor(fraction / std::pow(10.0, k)), 10.0)));
        }
    }
    return out;
}

std::optional<std::string> formatBprnt(Value value, int fractionDigits) {
    const double v = value.vacant ? 0.0 : value.number;
    const double scaled = std::round(v * std::pow(10.0, fractionDigits));
    if (!(scaled >= std::numeric_limits<std::int32_t>::min() && scaled <= std::numeric_limits<std::int32_t>::max())) {
        return std::nullopt;
    }
    const auto bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(scaled));
    std::string out;
    for (int shift = 24; shift >= 0; shift -= 8) {
        out += static_cast<char>((bits >> shift) & 0xFFu);
    }
    return out;
}

} // namespace m350::macro
