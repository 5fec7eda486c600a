#pragma once

#include <array>
#include <cstdint>

namespace m350::config {

// The controller's numbered parameters 0-999 (the M350 stores them as 1000 doubles; macros see
// parameter N as #(N+500)). Range checking and names live in the parameter catalogue.
class ParameterTable {
public:
    static constexpr int kCount = 1000;

    ParameterTable() = default;
    ParameterTable(const ParameterTable& other) : values_(other.values_) {}
    // Restoring saved values is a change like any other: the version moves on, never back.
    ParameterTable& operator=(const ParameterTable& other) {
        values_ = other.values_;
        ++version_;
        return *this;
    }

    double get(int number) const { return values_[static_cast<std::size_t>(number)]; }
    void set(int number, double value) {
        values_[static_cast<std::size_t>(number)] = value;
        ++version_;
    }
    static bool valid(int number) { return number >= 0 && number < kCount; }
    // Changes with every write, so a reader can keep what it computes from them until the next one.
    std::uint64_t version() const { return version_; }

private:
    std::uint64_t version_ = 0;
    std::array<double, kCount> values_{};
};

} // namespace m350::config
