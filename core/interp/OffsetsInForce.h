#pragma once

#include "core/interp/ModalState.h"
#include "core/interp/WorkOffsets.h"
#include "core/machine/MachineTypes.h"
#include "core/params/ParameterTable.h"

#include <array>
#include <bit>
#include <cstdint>

namespace m350::gcode {
struct Dialect;
}

namespace m350::interp {

// The offsets in force between machine and work coordinates: the active work system (G54-G59, a
// FANUC's G54.1 Pn, the M350's system in param 78), G52, the common offset, a FANUC's G92 shift, the
// M350 tool's Z offset (params 930-945, virtual tools 973-992) and G43/G44's length. Their sum is
// kept from block to block and computed again only when what it is computed from changed: it is
// asked for every block.
class OffsetsInForce {
public:
    // `state` is the interpreter's modal state, read as it stands.
    OffsetsInForce(const gcode::Dialect& dialect, const params::ParameterTable& parameters, const WorkOffsets& offsets,
                   const ModalState& state);

    // The active system's slot in WorkOffsets (1..6 for G54..G59, from 9 on G54.1 P1.., 0 for the
    // M350's G92 system).
    int activeSlot() const;
    // The tool in the spindle as the offsets know it: param 800 on the M350, the last T on a FANUC.
    int currentTool() const;
    // The Z offset of that tool on the M350 (0 elsewhere).
    double toolZOffset() const;
    // FANUC G43/G44 H: + or - the length of offset H as G43/G44 (or the last H under them) read it;
    // 0 under G49.
    double toolLengthOffset() const;
    // Total offset between machine and work coordinates for each axis, tool Z offset included.
    const machine::Axes& total() const {
        if (!cache_.known || !(inputs() == cache_.inputs)) {
            refresh();
        }
        return cache_.offset;
    }

private:
    // What total() is computed from: the versions of the offsets and the parameters (the M350's
    // work system, tool, magazine capacity and tool Z offsets), and as bit patterns (so -0.0 and NaN
    // compare exactly) the units, tool length mode, work system and latched length of the modal
    // state, which the interpreter writes in place.
    struct Inputs {
        std::uint64_t offsetsVersion = 0;
        std::uint64_t parametersVersion = 0;
        std::array<std::uint64_t, 5> modal{};
        bool operator==(const Inputs& other) const { // without a branch or memcmp a field
            std::uint64_t differ = (offsetsVersion ^ other.offsetsVersion) | (parametersVersion ^ other.parametersVersion);
            for (std::size_t i = 0; i < modal.size(); ++i) {
                differ |= modal[i] ^ other.modal[i];
            }
            return differ == 0;
        }
    };
    struct Cache {
        bool known = false;
        Inputs inputs;
        machine::Axes offset = machine::Axes::Zero();
    };
    Inputs inputs() const {
        return {offsets_.version(),
                parameters_.version(),
                {std::bit_cast<std::uint64_t>(state_.groups[6]), std::bit_cast<std::uint64_t>(state_.groups[8]),
                 std::bit_cast<std::uint64_t>(state_.groups[14]), std::bit_cast<std::uint64_t>(state_.lengthOffsetValue),
                 static_cast<std::uint64_t>(state_.additionalSystem)}};
    }
    void refresh() const;
    machine::Axes compute() const;

    const gcode::Dialect& dialect_;
    const params::ParameterTable& parameters_;
    const WorkOffsets& offsets_;
    const ModalState& state_;
    mutable Cache cache_;
};

} // namespace m350::interp
