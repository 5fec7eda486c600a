#pragma once

#include "core/params/ParameterTable.h"

#include <array>

namespace m350::params {

// The programming axes a machine has (X Y Z, then the 4th and 5th), as its parameters configure
// them: how many there are, what each is called and whether it turns.
//
// No M350 parameter holds the axis count (the controller reports it, read-only, in #1995); it
// follows from the drive assignment, params 488-492 (#988-#992, 1号-5号物理轴的编程轴: which
// programming axis each of the five drives obeys, 0 X .. 4 5th). The count reaches the last drive
// in use, one set to obey another axis than X (0, the factory value, leaves a drive unused), and the
// highest programming axis a drive moves; the axis-follow function (param 22 on) adds its follower
// (param 24). X Y Z are always there. So a dual-Y gantry (drive 4 obeys Y) has an A of its own, as
// the owners' fndzero.nc homes it and copies Y into it (#883 = #881).
struct AxisSetup {
    static constexpr int kAxes = 5;
    int count = 3;                                   // the axes 0 .. count-1 exist (#1995)
    std::array<char, kAxes> names{'X', 'Y', 'Z', 'A', 'B'}; // params 443/444 name the 4th/5th (3-5: A B C)
    std::array<bool, kAxes> rotary{};                // params 449/450: 1 = a rotary axis, in degrees

    bool present(int axis) const { return axis >= 0 && axis < count; }
};

AxisSetup axisSetup(const ParameterTable& parameters);

} // namespace m350::params
