#pragma once

#include <array>

namespace m350::interp {

// FANUC tool offset memory (Memory A): offsets 1-400, addressed by H for length (G43/G44) and by
// D for radius (G41/G42), and by macros as #2001-#2400. Offset 0 is always 0.
class ToolOffsets {
public:
    static constexpr int kCount = 400;

    double get(int number) const {
        return number >= 1 && number <= kCount ? values_[static_cast<std::size_t>(number - 1)] : 0.0;
    }
    void set(int number, double value) {
        if (number >= 1 && number <= kCount) {
            values_[static_cast<std::size_t>(number - 1)] = value;
        }
    }
    static bool valid(int number) { return number >= 1 && number <= kCount; }

private:
    std::array<double, kCount> values_{};
};

} // namespace m350::interp
