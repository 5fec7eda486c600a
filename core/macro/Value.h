#pragma once

#include <cmath>
#include <optional>

namespace m350::macro {

// A macro variable's content: a number, or FANUC's <vacant> (never assigned / #0).
// On the M350 nothing is ever vacant: unset variables read 0.
struct Value {
    double number = 0.0;
    bool vacant = false;

    static Value of(double v) { return Value{v, false}; }
    static Value empty() { return Value{0.0, true}; }

    // Arithmetic and GE/GT/LE/LT treat vacant as 0.
    double asNumber() const { return vacant ? 0.0 : number; }
    std::optional<double> toOptional() const { return vacant ? std::nullopt : std::optional<double>(number); }
};

} // namespace m350::macro
