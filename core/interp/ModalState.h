#pragma once

#include "core/interp/PlaneRotation.h"

#include <array>

namespace m350::interp {

// The modal state as FANUC numbers its groups, so #4001-#4022 read it directly:
// group 1 motion (0 1 2 3), 2 plane (17 18 19), 3 distance (90 91), 5 feed mode (94 95),
// 6 units (20 21), 7 cutter compensation (40 41 42), 8 tool length (43 44 49), 9 canned cycle (80..),
// 10 return level (98 99), 14 work system (54..59, 54.1 with `additionalSystem` its P), 16 coordinate
// rotation (68 69).
struct ModalState {
    std::array<double, 23> groups{};
    double feed = 0.0;        // F, mm/min
    double spindleSpeed = 0.0; // S
    int selectedTool = 0;      // T as last commanded
    int lengthOffset = 0;      // H
    double lengthOffsetValue = 0.0; // offset H as the last G43/G44 (or H under them) read it
    int radiusOffset = 0;      // D
    double lastM = 0.0;
    int additionalSystem = 0; // G54.1 P: 1.. while group 14 is 54.1 (#4130), else 0
    PlaneRotation rotation;   // while group 16 is 68

    ModalState() {
        groups[1] = 0;
        groups[2] = 17;
        groups[3] = 90;
        groups[5] = 94;
        groups[6] = 21;
        groups[7] = 40;
        groups[8] = 49;
        groups[9] = 80;
        groups[10] = 98;
        groups[14] = 54;
        groups[16] = 69;
    }

    int group(int g) const { return static_cast<int>(groups[static_cast<std::size_t>(g)]); }
    bool incremental() const { return group(3) == 91; }
    bool inches() const { return group(6) == 20; }
    bool rotating() const { return groups[16] == 68; }
};

} // namespace m350::interp
