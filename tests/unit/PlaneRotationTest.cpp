#include "core/interp/PlaneRotation.h"

#include <gtest/gtest.h>

#include <optional>

namespace m350::interp {
namespace {

machine::Axes at(double x, double y, double z = 0.0) {
    machine::Axes a = machine::Axes::Zero();
    a << x, y, z, 0.0, 0.0;
    return a;
}

void expectNear(const machine::Axes& actual, const machine::Axes& expected) {
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        EXPECT_NEAR(actual(axis), expected(axis), 1e-9) << "axis " << axis;
    }
}

TEST(PlaneRotation, AnAbsolutePointTurnsAboutTheCentre) {
    // G17 G68 X10 Y0 R90, then G90 X20 Y0: the point 10 mm right of the centre turns to 10 mm above
    PlaneRotation r(0, 1, {10.0, 0.0}, {0.0, 0.0}, 90.0);
    r.absoluteCommandSeen();
    expectNear(r.turned(at(0, 0, 5), 20.0, 0.0, false, machine::Axes::Zero()), at(10, 10, 5));
}

TEST(PlaneRotation, TheWorkOffsetIsAddedAfterTurning) {
    PlaneRotation r(0, 1, {0.0, 0.0}, {0.0, 0.0}, 90.0);
    r.absoluteCommandSeen();
    expectNear(r.turned(at(0, 0), 10.0, 0.0, false, at(100, 200)), at(100, 210));
}

TEST(PlaneRotation, AnIncrementalMoveIsTheWrittenOneTurned) {
    PlaneRotation r(0, 1, {50.0, 50.0}, {0.0, 0.0}, 90.0);
    expectNear(r.turned(at(3, 4), 10.0, std::nullopt, true, machine::Axes::Zero()), at(3, 14));
}

TEST(PlaneRotation, AnAxisLeftOutReadsFromWhereTheToolStoodUntilAnAbsoluteCommand) {
    // G68 X0 Y0 R90 with the tool at X10 Y0 (work); then X10 alone: Y reads as the tool's 0 in the
    // program's turned coordinates about where the tool stood, so the point is (10, 0) turned
    PlaneRotation r(0, 1, {0.0, 0.0}, {10.0, 0.0}, 90.0);
    expectNear(r.turned(at(10, 0), 10.0, std::nullopt, false, machine::Axes::Zero()), at(0, 10));
    // after the first absolute command the pivot is the centre: from (0, 10) the program stands at
    // (10, 0) in its own coordinates, and Y5 alone goes to (10, 5) turned
    r.absoluteCommandSeen();
    expectNear(r.turned(at(0, 10), std::nullopt, 5.0, false, machine::Axes::Zero()), at(-5, 10));
}

TEST(PlaneRotation, ABlockWithoutThePlanesAxesStaysWhereItIs) {
    PlaneRotation r(0, 1, {0.0, 0.0}, {0.0, 0.0}, 30.0);
    expectNear(r.turned(at(1, 2, 3), std::nullopt, std::nullopt, false, machine::Axes::Zero()), at(1, 2, 3));
}

TEST(PlaneRotation, TheG18PlaneTurnsZIntoX) {
    // G18: u = Z, v = X, counter-clockwise seen from +Y
    PlaneRotation r(2, 0, {0.0, 0.0}, {0.0, 0.0}, 90.0);
    Eigen::Vector3d arcCentre(0.0, 0.0, 1.0);
    r.turn(arcCentre);
    EXPECT_NEAR(arcCentre(0), 1.0, 1e-12);
    EXPECT_NEAR(arcCentre(1), 0.0, 1e-12);
    EXPECT_NEAR(arcCentre(2), 0.0, 1e-12);
}

} // namespace
} // namespace m350::interp
