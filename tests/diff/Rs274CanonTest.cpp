// How rs274's canonical output becomes machine positions (Rs274Canon.h). The inputs are rs274's own
// output for the programs in the comments, so these run where LinuxCNC is not installed too.
#include "tests/diff/Rs274Canon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using m350::testing::CanonRun;
using m350::testing::readCanonOutput;

void expectAt(const m350::testing::CanonMove& move, double x, double y, double z) {
    EXPECT_NEAR(move.machine[0], x, 1e-9) << move.call;
    EXPECT_NEAR(move.machine[1], y, 1e-9) << move.call;
    EXPECT_NEAR(move.machine[2], z, 1e-9) << move.call;
}

// G21 / G10 L2 P1 X100 Y200 Z50 / G54 G0 X0 Y0 Z0 / G53 G0 X7 Y8 Z9 / M2
TEST(Rs274Canon, WorkOffsetIsAddedBackAndG53PrintsInTheWorkFrame) {
    const CanonRun run = readCanonOutput(R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   12 N..... SET_G5X_OFFSET(1, 100.0000, 200.0000, 50.0000, 0.0000, 0.0000, 0.0000)
   14 N..... COMMENT("interpreter: continuing to use same coordinate system")
   15 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   22 N..... STRAIGHT_TRAVERSE(-93.0000, -192.0000, -41.0000, 0.0000, 0.0000, 0.0000)
   33 N..... PROGRAM_END()
)");
    ASSERT_EQ(run.moves.size(), 2u);
    EXPECT_TRUE(run.problems.empty());
    EXPECT_TRUE(run.programEnded);
    EXPECT_EQ(run.moves[0].kind, "rapid");
    expectAt(run.moves[0], 100, 200, 50);
    expectAt(run.moves[1], 7, 8, 9);
}

// G52 X10 Y10 / G0 X0 Y0 (G92 offset); G43 H1 with tool 1 12.7 mm long / G0 Z10
TEST(Rs274Canon, G92AndToolOffsetsAreAddedBack) {
    const CanonRun run =
        readCanonOutput(R"(   21 N..... SET_G92_OFFSET(10.0000, 10.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   22 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   23 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 12.7000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)
   24 N..... STRAIGHT_FEED(0.0000, 0.0000, 10.0000, 0.0000, 0.0000, 0.0000)
)");
    ASSERT_EQ(run.moves.size(), 2u);
    expectAt(run.moves[0], 10, 10, 0);
    EXPECT_EQ(run.moves[1].kind, "feed");
    expectAt(run.moves[1], 10, 10, 22.7);
    EXPECT_FALSE(run.programEnded);
}

// G18 G2 X10 Z0 I5 K0 / G19 G3 Y10 Z0 J5 K0 / G17 G2 X20 Y10 Z-5 I5 J0, from X0 Y0 Z0
TEST(Rs274Canon, ArcAxesFollowThePlane) {
    const CanonRun run = readCanonOutput(R"(   11 N..... SELECT_PLANE(CANON_PLANE_XZ)
   12 N..... ARC_FEED(0.0000, 10.0000, 0.0000, 5.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   13 N..... SELECT_PLANE(CANON_PLANE_YZ)
   14 N..... ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, 1, 10.0000, 0.0000, 0.0000, 0.0000)
   15 N..... SELECT_PLANE(CANON_PLANE_XY)
   16 N..... ARC_FEED(20.0000, 10.0000, 15.0000, 10.0000, -1, -5.0000, 0.0000, 0.0000, 0.0000)
)");
    ASSERT_EQ(run.moves.size(), 3u);
    constexpr double pi = std::numbers::pi;
    EXPECT_EQ(run.moves[0].kind, "arc");
    expectAt(run.moves[0], 10, 0, 0);
    EXPECT_NEAR(run.moves[0].arcLength, 5 * pi, 1e-9);
    expectAt(run.moves[1], 10, 10, 0);
    EXPECT_NEAR(run.moves[1].arcLength, 5 * pi, 1e-9);
    expectAt(run.moves[2], 20, 10, -5);
    EXPECT_NEAR(run.moves[2].arcLength, std::hypot(5 * pi, 5.0), 1e-9);
}

// From X10 Y0: G3 X0 Y10 I-10 J0 (a quarter), G2 X10 Y0 R-10 (three quarters), G2 X10 Y0 I-5 J0
// (a full turn)
TEST(Rs274Canon, ArcLengthTellsTheWayRound) {
    const CanonRun run =
        readCanonOutput(R"(    9 N..... STRAIGHT_TRAVERSE(10.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   11 N..... ARC_FEED(0.0000, 10.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   12 N..... ARC_FEED(10.0000, 0.0000, 10.0000, 10.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   13 N..... ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
)");
    ASSERT_EQ(run.moves.size(), 4u);
    constexpr double pi = std::numbers::pi;
    EXPECT_NEAR(run.moves[1].arcLength, 5 * pi, 1e-9);
    EXPECT_NEAR(run.moves[2].arcLength, 15 * pi, 1e-9);
    EXPECT_NEAR(run.moves[3].arcLength, 10 * pi, 1e-9);
}

// G20 after an offset written in G21: each number is in the unit in force when it was printed.
TEST(Rs274Canon, InchesAreScaledWhenPrinted) {
    const CanonRun run =
        readCanonOutput(R"(    9 N..... SET_G5X_OFFSET(1, 25.4000, 50.8000, 0.0000, 0.0000, 0.0000, 0.0000)
   13 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)
   14 N..... STRAIGHT_TRAVERSE(1.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   15 N..... SET_G5X_OFFSET(1, 2.0000, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   17 N..... STRAIGHT_TRAVERSE(0.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)
)");
    ASSERT_EQ(run.moves.size(), 2u);
    expectAt(run.moves[0], 50.8, 76.2, 0);
    expectAt(run.moves[1], 50.8, 76.2, 0);
}

// G10 L2 P1 X110 Y70 R-45 / G52 X-10 Y-20 / G0 X10 Y20 / G1 X30 Y20 / G2 X30 Y0 I0 J-10 (from X30 Y20)
TEST(Rs274Canon, ARotatedSystemTurnsTheProgramPositionWithItsG92Offset) {
    const CanonRun run = readCanonOutput(R"(    9 N..... SET_G5X_OFFSET(1, 110.0000, 70.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   10 N..... SET_XY_ROTATION(-45.0000)
   11 N..... SET_G92_OFFSET(-10.0000, -20.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   13 N..... STRAIGHT_TRAVERSE(10.0000, 20.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   15 N..... STRAIGHT_FEED(30.0000, 20.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   16 N..... ARC_FEED(30.0000, 0.0000, 30.0000, 10.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
)");
    ASSERT_EQ(run.moves.size(), 3u);
    EXPECT_TRUE(run.problems.empty());
    const double h = std::sqrt(0.5);
    expectAt(run.moves[0], 110, 70, 0);
    expectAt(run.moves[1], 110 + 20 * h, 70 - 20 * h, 0);
    expectAt(run.moves[2], 110 + 20 * h - 20 * h, 70 - 20 * h - 20 * h, 0);
    EXPECT_NEAR(run.moves[2].arcLength, 10 * std::numbers::pi, 1e-9); // a half circle, turned
}

TEST(Rs274Canon, ARotationWithoutAnAngleIsAProblem) {
    const CanonRun run = readCanonOutput("   10 N..... SET_XY_ROTATION()\n");
    EXPECT_EQ(run.problems.size(), 1u);
}

} // namespace
