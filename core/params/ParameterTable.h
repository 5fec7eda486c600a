#pragma once

#include "core/common/ChangeCount.h"

#include <array>
#include <cstdint>

namespace m350::params {

// The controller's numbered parameters 0-999 (the M350 stores them as 1000 doubles; macros see
// parameter N as #(N+500)). Range checking and names live in the parameter catalogue.
class ParameterTable {
public:
    static constexpr int kCount = 1000;

    double get(int number) const { return values_[static_cast<std::size_t>(number)]; }
    void set(int number, double value) {
        values_[static_cast<std::size_t>(number)] = value;
        version_.add();
    }
    static bool valid(int number) { return number >= 0 && number < kCount; }
    // Changes with every write and restore (ChangeCount), so a reader can keep what it computes
    // from the parameters until the next one.
    std::uint64_t version() const { return version_.value(); }

private:
    ChangeCount version_;
    std::array<double, kCount> values_{};
};

} // namespace m350::params
