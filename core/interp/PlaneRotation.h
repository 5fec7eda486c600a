#pragma once

#include "core/machine/MachineTypes.h"

#include <Eigen/Core>

#include <array>
#include <optional>

namespace m350::interp {

// G68's rotation of the program in the plane of axes u, v (G17: X Y, G18: Z X, G19: Y Z), about
// `centre` (work coordinates) by `degrees`, counter-clockwise seen from the plane's normal.
class PlaneRotation {
public:
    PlaneRotation() = default;
    // `toolAtStart`: where the tool stood at G68 (work coordinates of u, v). FANUC: until an
    // absolute command names a plane axis, the program turns about there (its incremental moves),
    // so that is where omitted plane axes read from.
    PlaneRotation(int u, int v, std::array<double, 2> centre, std::array<double, 2> toolAtStart, double degrees);

    int u() const { return u_; }
    int v() const { return v_; }

    // `from` (machine coordinates) moved in the plane by the block's words, as the turned program
    // counts them: `du`, `dv` in mm where the block names that axis, incremental or absolute
    // (work coordinates; `workOffset` between them and machine coordinates).
    machine::Axes turned(const machine::Axes& from, std::optional<double> du, std::optional<double> dv,
                         bool incremental, const machine::Axes& workOffset) const;
    // A vector in the plane (an arc's I J K), turned.
    void turn(Eigen::Vector3d& vector) const;
    // From the first absolute command that names an axis of the plane on, the program turns about
    // the centre.
    void absoluteCommandSeen() { absoluteSeen_ = true; }
    bool absoluteSeen() const { return absoluteSeen_; }

private:
    int u_ = 0;
    int v_ = 1;
    std::array<double, 2> centre_{};
    std::array<double, 2> toolAtStart_{};
    bool absoluteSeen_ = false;
    double cosine_ = 1.0;
    double sine_ = 0.0;
};

} // namespace m350::interp
