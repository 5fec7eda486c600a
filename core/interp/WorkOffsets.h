#pragma once

#include "core/common/ChangeCount.h"
#include "core/machine/MachineTypes.h"

#include <cstdint>
#include <vector>

namespace m350::interp {

// Coordinate-system offsets, in the slot order both dialects' variables use:
// 0 = G92 (M350: its own system, #800-#804), 1..6 = G54..G59, 7 = G52 local, 8 = common / EXT,
// then FANUC's additional systems G54.1 P1, P2, ... (as many as the machine has).
class WorkOffsets {
public:
    static constexpr int kSlots = 9; // the systems every machine has
    static constexpr int kG92 = 0;
    static constexpr int kG52 = 7;
    static constexpr int kCommon = 8;
    static constexpr int kFirstAdditional = 9; // G54.1 P1 (macro::VariableMap::kFirstAdditionalSlot)

    static constexpr int additionalSlot(int p) { return kFirstAdditional + p - 1; }

    // G54.1 P1-Pcount; a smaller count drops the systems beyond it.
    void setAdditionalCount(int count) {
        offsets_.resize(static_cast<std::size_t>(kSlots + count), machine::Axes::Zero());
        version_.add();
    }
    int additionalCount() const { return slotCount() - kSlots; }
    int slotCount() const { return static_cast<int>(offsets_.size()); }

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
    std::vector<machine::Axes> offsets_ = std::vector<machine::Axes>(kSlots, machine::Axes::Zero());
};

} // namespace m350::interp
