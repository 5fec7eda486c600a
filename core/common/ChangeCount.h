#pragma once

#include <cstdint>

namespace m350 {

// How often a value has changed, for readers that keep what they computed from it until the next
// change (ParameterTable, WorkOffsets). A copy starts its own count; assigning a saved value back
// is a change like any other, so the count moves on, never back.
class ChangeCount {
public:
    ChangeCount() = default;
    ChangeCount(const ChangeCount&) {}
    ChangeCount& operator=(const ChangeCount&) {
        ++count_;
        return *this;
    }

    void add() { ++count_; }
    std::uint64_t value() const { return count_; }

private:
    std::uint64_t count_ = 0;
};

} // namespace m350
