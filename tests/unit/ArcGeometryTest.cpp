#include "core/machine/ArcGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using m350::machine::Arc;
using m350::machine::ArcError;
using m350::machine::ArcSpec;
using m350::machine::makeArc;
using m350::machine::Axes;
using m350::machine::Plane;

constexpr double kPi = std::numbers::pi;
constexpr double kHalfRoot2 = 7.0710678118654755; // 10 * sin(45 deg)

Axes at(double x, double y, double z, double a = 0.0, double b = 0.0) {
    Axes p;
    p << x, y, z, a, b;
    return p;
}

ArcSpec withCenter(Plane plane, bool clockwise, const Axes& start, const Axes& end, double i, double j, double k) {
    ArcSpec spec{start, end, plane, clockwise, Eigen::Vector3d(i, j, k), std::nullopt, 0};
    return spec;
}

ArcSpec withRadius(Plane plane, bool clockwise, const Axes& start, const Axes& end, double r) {
    ArcSpec spec{start, end, plane, clockwise, std::nullopt, r, 0};
    return spec;
}

Arc arcOf(const ArcSpec& spec) {
    auto result = makeArc(spec);
    if (const auto* error = std::get_if<ArcError>(&result)) {
        ADD_FAILURE() << "unexpected error: " << error->message;
        return {};
    }
    return std::get<Arc>(result);
}

std::string errorOf(const ArcSpec& spec) {
    auto result = makeArc(spec);
    if (const auto* error = std::get_if<ArcError>(&result)) return error->message.english();
    ADD_FAILURE() << "expected an error";
    return {};
}

void expectNear(const Axes& actual, const Axes& expected, double tolerance = 1e-9) {
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "axis " << i;
}

TEST(ArcGeometry, QuarterClockwiseInXY) {
    const Arc arc = arcOf(withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), -10, 0, 0));
    EXPECT_NEAR(arc.center.norm(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(arc.radius, 10.0);
    EXPECT_NEAR(arc.sweep, -kPi / 2, 1e-12);
    EXPECT_NEAR(arc.length, 15.708, 5e-4);
    EXPECT_DOUBLE_EQ(arc.helixLength, 0.0);
    expectNear(arc.pointAt(arc.length / 2), at(kHalfRoot2, -kHalfRoot2, 0));
}

TEST(ArcGeometry, SameEndsCounterclockwiseGoTheLongWay) {
    const Arc arc = arcOf(withCenter(Plane::XY, false, at(10, 0, 0), at(0, -10, 0), -10, 0, 0));
    EXPECT_NEAR(arc.sweep, 3 * kPi / 2, 1e-12);
    EXPECT_NEAR(arc.length, 47.124, 5e-4);
    expectNear(arc.pointAt(arc.length / 3), at(0, 10, 0));
    expectNear(arc.pointAt(arc.length * 2 / 3), at(-10, 0, 0));
}

TEST(ArcGeometry, RadiusSignSelectsShortOrLongArc) {
    const Axes start = at(10, 0, 0), end = at(0, -10, 0);
    const Arc shortArc = arcOf(withRadius(Plane::XY, true, start, end, 10.0));
    EXPECT_NEAR(shortArc.center.norm(), 0.0, 1e-9);
    EXPECT_NEAR(shortArc.sweep, -kPi / 2, 1e-9);
    const Arc longArc = arcOf(withRadius(Plane::XY, true, start, end, -10.0));
    EXPECT_NEAR(longArc.center.x(), 10.0, 1e-9);
    EXPECT_NEAR(longArc.center.y(), -10.0, 1e-9);
    EXPECT_NEAR(longArc.sweep, -3 * kPi / 2, 1e-9);
    EXPECT_NEAR(longArc.length, 15 * kPi, 1e-9);
    // Counterclockwise, the short arc bulges the other way, around (10, -10).
    const Arc ccw = arcOf(withRadius(Plane::XY, false, start, end, 10.0));
    EXPECT_NEAR(ccw.center.x(), 10.0, 1e-9);
    EXPECT_NEAR(ccw.sweep, kPi / 2, 1e-9);
}

TEST(ArcGeometry, RadiusTakesPrecedenceOverCenter) {
    ArcSpec spec = withRadius(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), -10.0);
    spec.centerOffset = Eigen::Vector3d(-10, 0, 0);
    EXPECT_NEAR(arcOf(spec).sweep, -3 * kPi / 2, 1e-9);
}

TEST(ArcGeometry, SemicircleAcceptsRadiusRoundedShort) {
    const Arc arc = arcOf(withRadius(Plane::XY, true, at(10, 0, 0), at(-10, 0, 0), 9.9995));
    EXPECT_NEAR(arc.center.norm(), 0.0, 1e-9);
    EXPECT_NEAR(arc.radius, 10.0, 1e-9);
    EXPECT_NEAR(arc.sweep, -kPi, 1e-9);
    expectNear(arc.pointAt(arc.length / 2), at(0, -10, 0));
}

TEST(ArcGeometry, FullCircleWithCenter) {
    const Arc cw = arcOf(withCenter(Plane::XY, true, at(10, 0, 0), at(10, 0, 0), -10, 0, 0));
    EXPECT_NEAR(cw.sweep, -2 * kPi, 1e-12);
    EXPECT_NEAR(cw.length, 20 * kPi, 1e-9);
    expectNear(cw.pointAt(cw.length / 4), at(0, -10, 0));
    const Arc ccw = arcOf(withCenter(Plane::XY, false, at(10, 0, 0), at(10, 0, 0), -10, 0, 0));
    EXPECT_NEAR(ccw.sweep, 2 * kPi, 1e-12);
    expectNear(ccw.pointAt(ccw.length / 4), at(0, 10, 0));
}

TEST(ArcGeometry, ExtraTurnsAddFullCircles) {
    ArcSpec spec = withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), -10, 0, 0);
    spec.turns = 2;
    EXPECT_NEAR(arcOf(spec).sweep, -kPi / 2 - 4 * kPi, 1e-12);
    spec.turns = -1;
    EXPECT_EQ(errorOf(spec), "arc turn count must not be negative");
}

TEST(ArcGeometry, HelicalFullCircle) {
    const Arc arc = arcOf(withCenter(Plane::XY, false, at(10, 0, 0), at(10, 0, -5), -10, 0, 0));
    EXPECT_DOUBLE_EQ(arc.helixLength, -5.0);
    EXPECT_NEAR(arc.length, std::sqrt(std::pow(20 * kPi, 2) + 25.0), 1e-9);
    EXPECT_NEAR(arc.length, 63.0304, 1e-4);
    expectNear(arc.pointAt(arc.length / 4), at(0, 10, -1.25));
    expectNear(arc.pointAt(arc.length / 2), at(-10, 0, -2.5));
    EXPECT_EQ(arc.pointAt(arc.length), arc.end);
}

TEST(ArcGeometry, RotaryAxesMoveLinearlyAndAddToLength) {
    const Arc arc = arcOf(withCenter(Plane::XY, true, at(10, 0, 0, 0, 10), at(0, -10, 2, 90, 10), -10, 0, 0));
    EXPECT_NEAR(arc.length, std::sqrt(25 * kPi * kPi + 4 + 8100), 1e-9);
    expectNear(arc.pointAt(arc.length / 2), at(kHalfRoot2, -kHalfRoot2, 1, 45, 10));
}

TEST(ArcGeometry, PointAtClampsAndHitsEndsExactly) {
    const Arc arc = arcOf(withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10.0015, 0), -10, 0, 0));
    EXPECT_NEAR(arc.radius, 10.00075, 1e-12);
    EXPECT_EQ(arc.pointAt(0.0), arc.start);
    EXPECT_EQ(arc.pointAt(-3.0), arc.start);
    EXPECT_EQ(arc.pointAt(arc.length), arc.end);
    EXPECT_EQ(arc.pointAt(arc.length + 1.0), arc.end);
    expectNear(arc.pointAt(arc.length * (1 - 1e-12)), arc.end, 1e-9);
}

// G18 is seen from +Y, so the in-plane pair is (Z, X): turning from +X toward +Z is clockwise.
TEST(ArcGeometry, ZXPlaneClockwiseTurnsFromXTowardZ) {
    const Axes start = at(10, 0, 0), end = at(0, 0, 10);
    const Arc g2 = arcOf(withCenter(Plane::ZX, true, start, end, -10, 0, 0));
    EXPECT_NEAR(g2.sweep, -kPi / 2, 1e-12);
    EXPECT_NEAR(g2.length, 5 * kPi, 1e-9);
    expectNear(g2.pointAt(g2.length / 2), at(kHalfRoot2, 0, kHalfRoot2));
    const Arc g3 = arcOf(withCenter(Plane::ZX, false, start, end, -10, 0, 0));
    EXPECT_NEAR(g3.sweep, 3 * kPi / 2, 1e-12);
    expectNear(g3.pointAt(g3.length / 2), at(-kHalfRoot2, 0, -kHalfRoot2));
    const Arc r = arcOf(withRadius(Plane::ZX, true, start, end, 10.0));
    EXPECT_NEAR(r.center.norm(), 0.0, 1e-9);
    EXPECT_NEAR(r.sweep, -kPi / 2, 1e-9);
}

TEST(ArcGeometry, ZXPlaneHelixRunsAlongY) {
    const Arc arc = arcOf(withCenter(Plane::ZX, true, at(10, 0, 0), at(0, 4, 10), -10, 0, 0));
    EXPECT_DOUBLE_EQ(arc.helixLength, 4.0);
    EXPECT_NEAR(arc.length, std::sqrt(25 * kPi * kPi + 16), 1e-9);
    expectNear(arc.pointAt(arc.length / 2), at(kHalfRoot2, 2, kHalfRoot2));
}

// G19 is seen from +X with the pair (Y, Z): turning from +Y toward +Z is counterclockwise.
TEST(ArcGeometry, YZPlaneCounterclockwiseTurnsFromYTowardZ) {
    const Axes start = at(3, 10, 0), end = at(3, 0, 10);
    const Arc g3 = arcOf(withCenter(Plane::YZ, false, start, end, 0, -10, 0));
    EXPECT_NEAR(g3.sweep, kPi / 2, 1e-12);
    EXPECT_NEAR(g3.center.x(), 3.0, 1e-12);
    expectNear(g3.pointAt(g3.length / 2), at(3, kHalfRoot2, kHalfRoot2));
    const Arc g2 = arcOf(withCenter(Plane::YZ, true, start, end, 0, -10, 0));
    EXPECT_NEAR(g2.sweep, -3 * kPi / 2, 1e-12);
    expectNear(g2.pointAt(g2.length / 2), at(3, -kHalfRoot2, -kHalfRoot2));
}

TEST(ArcGeometry, RadiusCannotDescribeFullCircle) {
    EXPECT_EQ(errorOf(withRadius(Plane::XY, true, at(10, 0, 0), at(10, 0, -5), 10.0)),
              "R cannot describe a full circle: use I/J/K");
}

TEST(ArcGeometry, RadiusSmallerThanHalfChord) {
    EXPECT_EQ(errorOf(withRadius(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), 5.0)),
              "R 5.000 is smaller than half the distance between start and end (7.071)");
    EXPECT_EQ(errorOf(withRadius(Plane::XY, true, at(10, 0, 0), at(-10, 0, 0), -9.998)),
              "R -9.998 is smaller than half the distance between start and end (10.000)");
}

TEST(ArcGeometry, ZeroRadiusOrNoCenter) {
    EXPECT_EQ(errorOf(withRadius(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), 0.0)), "R must not be zero");
    ArcSpec none = withRadius(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), 1.0);
    none.radius.reset();
    EXPECT_EQ(errorOf(none), "G2/G3 needs I/J/K or R");
    EXPECT_EQ(errorOf(withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10, 0), 0, 0, 0)),
              "arc radius is zero: the center is on the start or end point");
}

TEST(ArcGeometry, EndPointOffTheCircle) {
    EXPECT_EQ(errorOf(withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10.5, 0), -10, 0, 0)),
              "arc end point is not on the circle: radius at start 10.000, at end 10.500");
    // 0.0026 mm is beyond the absolute tolerance even though it is only 0.026 % of the radius.
    EXPECT_EQ(errorOf(withCenter(Plane::XY, true, at(10, 0, 0), at(0, -10.0026, 0), -10, 0, 0)),
              "arc end point is not on the circle: radius at start 10.000, at end 10.003");
    // 0.0018 mm is within 0.002 mm but 0.18 % of a 1 mm radius.
    EXPECT_EQ(errorOf(withCenter(Plane::XY, true, at(1, 0, 0), at(0, -1.0018, 0), -1, 0, 0)),
              "arc end point is not on the circle: radius at start 1.000, at end 1.002");
}

} // namespace
