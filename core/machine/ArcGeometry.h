#pragma once

#include "core/common/Message.h"
#include "core/machine/MachineTypes.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <variant>

namespace m350::machine {

// Orientation convention (FANUC 0i, LinuxCNC): each plane is given as a right-handed pair (u, v)
// with u x v = the plane normal w, and "clockwise" is as seen from +w looking toward -w:
//   G17: u = X, v = Y, w = Z      G18: u = Z, v = X, w = Y      G19: u = Y, v = Z, w = X
// G18 is the trap: the pair is Z->X, not X->Z, because X x Z = -Y. Seen from +Y, turning from +X
// toward +Z is clockwise, so G2 X0 Z10 I-10 from X10 Z0 is the quarter arc, not the three-quarter one.
// (A drawing with X right and Z up is viewed from -Y, the mirror image of the programmer's view.)

// What a G2/G3 block says, already converted to machine coordinates in mm.
struct ArcSpec {
    machine::Axes start = machine::Axes::Zero();
    machine::Axes end = machine::Axes::Zero();
    machine::Plane plane = machine::Plane::XY;
    bool clockwise = true;                        // G2 true, G3 false
    std::optional<Eigen::Vector3d> centerOffset;  // I J K, incremental from start; ignored if R is given
    std::optional<double> radius;                 // R: > 0 the arc of at most 180 deg, < 0 the larger one
    int turns = 0;                                // extra full turns (LinuxCNC P minus one)
};

struct Arc {
    Eigen::Vector3d center = Eigen::Vector3d::Zero(); // X Y Z; the normal coordinate is the start's
    double radius = 0.0;       // mean of the start and end radii
    double sweep = 0.0;        // signed radians, + = counterclockwise seen from +normal
    double helixLength = 0.0;  // signed travel along the plane normal, end minus start
    double length = 0.0;       // sqrt((radius*|sweep|)^2 + helix^2 + (A,B travel)^2)
    machine::Plane plane = machine::Plane::XY;
    machine::Axes start = machine::Axes::Zero();
    machine::Axes end = machine::Axes::Zero();

    // Position after path distance s (clamped to 0..length), at uniform speed along the helix.
    machine::Axes pointAt(double s) const;
};

// Why a G2/G3 block describes no arc, by message id (the interpreter raises it on the block).
struct ArcError {
    Message message;
};

std::variant<Arc, ArcError> makeArc(const ArcSpec& spec);

} // namespace m350::machine
