#pragma once

#include <array>
#include <string>
#include <vector>

namespace m350::testing {

// X, Y, Z in millimetres.
using Point = std::array<double, 3>;

// One motion call of LinuxCNC's canonical output, its end point in machine coordinates.
struct CanonMove {
    std::string kind; // "rapid" (STRAIGHT_TRAVERSE), "feed" (STRAIGHT_FEED) or "arc" (ARC_FEED)
    Point machine{};
    double arcLength = 0.0; // arcs: the path length in mm, helix included
    std::string call;       // the line as rs274 printed it
};

struct CanonRun {
    std::vector<CanonMove> moves;
    bool programEnded = false;         // PROGRAM_END() was printed (M2 / M30 reached)
    std::vector<std::string> problems; // calls this reader cannot turn into machine positions
};

// Reads what `rs274 -g` prints (one canonical call a line) and follows the offsets it announces.
//
// rs274 prints motion in its canonical frame: the program's coordinates with the work offset
// (SET_G5X_OFFSET), the G92/G52 offset (SET_G92_OFFSET) and the tool length offset
// (USE_TOOL_LENGTH_OFFSET) taken out, in the length unit of the last USE_LENGTH_UNITS. Found by
// experiment: with G10 L2 P1 X100 and G54 active, `G53 G0 X7` prints STRAIGHT_TRAVERSE(-93, ...);
// with G52 X10 (G92 offset 10), `G0 X0` prints X0; with G43 H1 and a 12.7 mm tool, `G0 Z10` prints
// Z10 beside USE_TOOL_LENGTH_OFFSET(0 0 12.7, ...). So the machine position is
// canonical + G5x + G92 + tool offset, every term scaled to millimetres. A rotation of the G5x
// system (G10 L2 R, announced as SET_XY_ROTATION) turns the program position plus the G92 offset
// about Z before the G5x and tool offsets are added, as LinuxCNC's emccanon.cc does.
//
// ARC_FEED(first_end, second_end, first_centre, second_centre, turns, axis_end, a, b, c) names its
// axes by the plane of the last SELECT_PLANE: XY -> (X, Y, axis Z), XZ -> (Z, X, axis Y),
// YZ -> (Y, Z, axis X). `turns` is +n for counter-clockwise (seen from the plane's positive normal,
// first axis toward second), -n for clockwise, going round n - 1 extra times; an arc that ends where
// it starts is a full turn. The arc's length follows from its start (the previous end point), its
// centre, its end and its turns: what separates the short way from the long one, and G2 from G3
// (all but the half circle, whose two ways are equally long).
CanonRun readCanonOutput(const std::string& output);

} // namespace m350::testing
