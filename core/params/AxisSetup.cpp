#include "core/params/AxisSetup.h"

#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>

namespace m350::params {

namespace {

constexpr int kDriveAxisFirst = 488;  // 488-492: the programming axis drive 1..5 obeys (0 X .. 4 5th)
constexpr int kDrives = 5;
constexpr int kFollowOn = 22;         // 加工中轴随动功能: 1 = an axis follows another while machining
constexpr int kFollower = 24;         // 随动功能跟随轴: the following axis (0 X .. 3 4th)
constexpr int kFourthAxisName = 443;  // 443/444: 0 X, 1 Y, 2 Z, 3 A, 4 B, 5 C
constexpr char kLetters[] = {'X', 'Y', 'Z', 'A', 'B', 'C'};

// The programming axis a select parameter names, or -1 when its value is not one (0..4).
int programmingAxis(double value) {
    if (!std::isfinite(value) || value != std::round(value) || value < 0.0 || value >= AxisSetup::kAxes) {
        return -1;
    }
    return static_cast<int>(value);
}

} // namespace

AxisSetup axisSetup(const ParameterTable& parameters) {
    AxisSetup out;
    for (int drive = 1; drive <= kDrives; ++drive) {
        const int axis = programmingAxis(parameters.get(kDriveAxisFirst + drive - 1));
        if (axis > 0) {
            out.count = std::max({out.count, drive, axis + 1});
        }
    }
    if (parameters.get(kFollowOn) == 1.0) {
        out.count = std::max(out.count, programmingAxis(parameters.get(kFollower)) + 1);
    }
    for (int axis = 3; axis < AxisSetup::kAxes; ++axis) {
        const auto i = static_cast<std::size_t>(axis);
        // 3-5 name it A, B or C; 0-2 would give it the letter of X, Y or Z (and a folder that
        // leaves the parameter out has 0), so the axis keeps its own letter then
        const double name = parameters.get(kFourthAxisName + axis - 3);
        if (name == 3.0 || name == 4.0 || name == 5.0) {
            out.names[i] = kLetters[static_cast<int>(name)];
        }
        out.rotary[i] = parameters.get(param::kFourthAxisType + axis - 3) != 0.0;
    }
    return out;
}

} // namespace m350::params
