#pragma once

#include "core/common/ChangeCount.h"
#include "core/machine/MachineTypes.h"

#include <array>
#include <cstdint>

namespace m350::interp {

// Coordinate-system offsets, in the slot order both dialects' variables use:
// 0 = G92 (M350: its own system, #800-#804), 1..6 = G54..G59, 7 = G52 local, 8 = common / EXT.
class WorkOffsets {
public:
    static constexpr int kSlots = 9;
    static constexpr int kG92 = 0;
    static constexpr int kG52 = 7;
    static constexpr int kCommon = 8;

    double get(int slot, int axis) const { return offsets_[static_cast<std::size_t>(slot)](axis); }
    void set(int slot, int axis, double value) {
        offsets_[static_cast<std::size_t>(slot)](axis) = value;
        version_.add();
    }
    const machine::Axes& slot(int s) const { return offsets_[static_cast<std::size_t>(s)]; }
    // Changes with every write and restore (ChangeCount), so a reader can keep a sum of offsets
    // until the next one.
    std::uint64_t version() const { return version_.value(); }

private:
    ChangeCount version_;
    std::array<machine::Axes, kSlots> offsets_{machine::Axes::Zero(), machine::Axes::Zero(), machine::Axes::Zero(),
                                               machine::Axes::Zero(), machine::Axes::Zero(), machine::Axes::Zero(),
                                               machine::Axes::Zero(), machine::Axes::Zero(), machine::Axes::Zero()};
};

} // namespace m350::interp
