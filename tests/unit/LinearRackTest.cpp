// The fixed linear rack as a device: where the tools are after each signal and move, and what a
// wrong move or signal does to the hardware.
#include "core/devices/LinearRack.h"

#include <gtest/gtest.h>

namespace {

using m350::Message;
using m350::devices::LinearRack;
using Eigen::Vector3d;

// Three pockets 60 mm apart at Y5 Z-80, opening toward +Y; T1 in the spindle, T2 and T3 in 2, 3.
LinearRack rack() {
    LinearRack::Geometry g;
    g.pockets = {Vector3d(50, 5, -80), Vector3d(110, 5, -80), Vector3d(170, 5, -80)};
    return LinearRack(g, {0, 2, 3}, 1);
}

// Runs moves through the rack; the first complaint ends it.
std::optional<Message> path(LinearRack& r, std::initializer_list<Vector3d> points, bool rapid = false,
                            bool turning = false) {
    const Vector3d* previous = nullptr;
    for (const Vector3d& p : points) {
        if (previous) {
            if (auto crash = r.move(*previous, p, rapid, turning, 0.0)) {
                return crash;
            }
        }
        previous = &p;
    }
    return std::nullopt;
}

// The manual's side-loading change, T1 -> T2: return T1 to pocket 1 along Y, pick T2 from above.
TEST(LinearRack, AChangeMovesTheToolsWhereTheyBelong) {
    LinearRack r = rack();
    EXPECT_FALSE(path(r, {{0, 0, 0}, {0, 60, 0}, {50, 60, 0}, {50, 60, -80}, {50, 5, -80}}));
    EXPECT_FALSE(r.drawbar(true, {50, 5, -80}));
    EXPECT_EQ(r.pocketTool(1), 1);
    EXPECT_EQ(r.spindleTool(), 0);
    EXPECT_FALSE(path(r, {{50, 5, -80}, {50, 5, 0}, {110, 5, 0}, {110, 5, -40}, {110, 5, -80}}));
    EXPECT_FALSE(r.drawbar(false, {110, 5, -80}));
    EXPECT_EQ(r.spindleTool(), 2);
    EXPECT_FALSE(path(r, {{110, 5, -80}, {110, 60, -80}, {110, 60, 0}}));
    EXPECT_EQ(r.pocketTool(1), 1);
    EXPECT_EQ(r.pocketTool(2), 0);
    EXPECT_EQ(r.pocketTool(3), 3);
}

TEST(LinearRack, PushingAToolIntoAnOccupiedPocket) {
    LinearRack r = rack();
    EXPECT_EQ(path(r, {{110, 60, -80}, {110, 5, -80}}),
              "T1 in the spindle ran into T2 in pocket 2 (moving from X110.000 Y60.000 Z-80.000 to X110.000 Y5.000 Z-80.000)");
}

TEST(LinearRack, MovingSidewaysWhileClampedInAFork) {
    LinearRack r = rack();
    EXPECT_FALSE(path(r, {{50, 60, -80}, {50, 5, -80}}));
    EXPECT_EQ(path(r, {{50, 5, -80}, {50, 5, 0}}),
              "moved Z while T1 was clamped in the fork of pocket 1: the fork and the tool are wrecked at "
              "X50.000 Y5.000 Z-80.000");
}

TEST(LinearRack, AHeldToolEntersAForkAlongYOnly) {
    LinearRack r = rack();
    EXPECT_EQ(path(r, {{50, 5, 0}, {50, 5, -80}}),
              "T1 in the spindle hit the fork of pocket 1: a tool enters it along Y only (moving from X50.000 Y5.000 "
              "Z0.000 to X50.000 Y5.000 Z-80.000)");
}

TEST(LinearRack, ReleasingWithNoPocketUnderTheToolDropsIt) {
    LinearRack r = rack();
    EXPECT_EQ(r.drawbar(true, {300, 200, -10}),
              "T1 dropped: the drawbar was released at X300.000 Y200.000 Z-10.000 with no pocket under the tool (it "
              "fell onto the table)");
    EXPECT_EQ(r.spindleTool(), 0);
    ASSERT_EQ(r.droppedTools().size(), 1u);
    EXPECT_EQ(r.droppedTools()[0].tool, 1);
    EXPECT_EQ(r.droppedTools()[0].at, Eigen::Vector3d(300, 200, -10));
}

TEST(LinearRack, ComingDownOntoAToolClampedOrTurning) {
    LinearRack r = rack();
    EXPECT_FALSE(path(r, {{50, 60, -80}, {50, 5, -80}}));
    r.drawbar(true, {50, 5, -80});
    EXPECT_FALSE(path(r, {{50, 5, -80}, {50, 5, 0}, {110, 5, 0}}));
    LinearRack clamped = r;
    clamped.drawbar(false, {110, 5, 0});
    EXPECT_EQ(path(clamped, {{110, 5, 0}, {110, 5, -80}}),
              "came down onto T2 in pocket 2 with the drawbar clamped: release it (M154) before coming down");
    EXPECT_EQ(path(r, {{110, 5, 0}, {110, 5, -80}}, false, true),
              "came down onto T2 in pocket 2 with the spindle turning: stop it (M05) and wait for it (M300) first");
}

TEST(LinearRack, AnEmptyNoseRunningSidewaysIntoATool) {
    LinearRack r = rack();
    EXPECT_FALSE(path(r, {{50, 60, -80}, {50, 5, -80}}));
    r.drawbar(true, {50, 5, -80});
    LinearRack still = r;
    // still around the stud of the tool it just left
    EXPECT_EQ(path(still, {{50, 5, -80}, {50, 5, -70}, {60, 5, -70}}),
              "the spindle nose ran into T1 in pocket 1 (moving from X50.000 Y5.000 Z-70.000 to X60.000 Y5.000 "
              "Z-70.000)");
    EXPECT_EQ(path(r, {{50, 5, -80}, {50, 5, -40}, {80, 5, -40}, {80, 5, -70}, {200, 5, -70}}),
              "the spindle nose ran into T2 in pocket 2 (moving from X80.000 Y5.000 Z-70.000 to X200.000 Y5.000 "
              "Z-70.000)");
}

TEST(LinearRack, RapidThroughTheMagazineZone) {
    LinearRack r = rack();
    EXPECT_EQ(path(r, {{0, 20, -60}, {300, 20, -60}}, true),
              "rapid move through the magazine zone at pocket 1, from X0.000 Y20.000 Z-60.000 to X300.000 Y20.000 "
              "Z-60.000: move near the rack at feed (G01 / G53 ... F)");
    EXPECT_FALSE(path(r, {{0, 20, 0}, {300, 20, 0}}, true)); // high above it is fine
}

} // namespace

namespace {

// Top loading: tools go down into their forks and come up out of them.
LinearRack topRack() {
    LinearRack::Geometry g;
    g.loading = LinearRack::Loading::Top;
    g.forkDepth = 40;
    g.pockets = {Vector3d(100, 400, -95), Vector3d(180, 400, -95)};
    return LinearRack(g, {0, 2}, 1);
}

TEST(LinearRack, TopLoadingChange) {
    LinearRack r = topRack();
    EXPECT_FALSE(path(r, {{0, 0, 0}, {100, 400, 0}, {100, 400, -95}}));
    EXPECT_FALSE(r.drawbar(true, {100, 400, -95}));
    EXPECT_FALSE(path(r, {{100, 400, -95}, {100, 400, 0}, {180, 400, 0}, {180, 400, -95}}));
    EXPECT_FALSE(r.drawbar(false, {180, 400, -95}));
    EXPECT_FALSE(path(r, {{180, 400, -95}, {180, 400, 0}}));
    EXPECT_EQ(r.spindleTool(), 2);
    EXPECT_EQ(r.pocketTool(1), 1);
    EXPECT_EQ(r.pocketTool(2), 0);
}

TEST(LinearRack, TopLoadingHeldToolMovingSidewaysLowHitsTheForks) {
    LinearRack r = topRack();
    EXPECT_EQ(path(r, {{0, 400, -80}, {300, 400, -80}}),
              "T1 in the spindle hit the fork of pocket 1: a tool enters it along Z only (moving from X0.000 Y400.000 "
              "Z-80.000 to X300.000 Y400.000 Z-80.000)");
    LinearRack past = topRack();
    EXPECT_EQ(path(past, {{150, 400, -80}, {300, 400, -80}}),
              "T1 in the spindle ran into T2 in pocket 2 (moving from X150.000 Y400.000 Z-80.000 to X300.000 Y400.000 "
              "Z-80.000)");
}

} // namespace

// The inline test the magazine driver runs first: a move far from every pocket, with nothing
// engaged, needs no look from move(); one near the rack, or any while a fork holds the tool, does.
TEST(LinearRack, OnlyAMoveFarFromTheRackPassesWithoutALook) {
    LinearRack r = rack();
    EXPECT_TRUE(r.passesFar({0, 300, 0}, {500, 300, 0}));
    EXPECT_TRUE(r.passesFar({-200, 0, 0}, {-100, 0, -80}));
    EXPECT_FALSE(r.passesFar({0, 300, 0}, {0, 300, 0}));     // no move: move() keeps the last one
    EXPECT_FALSE(r.passesFar({50, 60, -80}, {50, 5, -80}));  // into the fork of pocket 1
    EXPECT_FALSE(r.passesFar({0, 0, -70}, {200, 0, -70}));   // along the row of pockets
    EXPECT_FALSE(path(r, {{50, 60, -80}, {50, 5, -80}}));    // T1 into pocket 1: the fork holds it
    EXPECT_FALSE(r.passesFar({0, 300, 0}, {500, 300, 0}));
    EXPECT_TRUE(path(r, {{50, 5, -80}, {0, 300, 0}}));       // and a move away sideways wrecks it
}

// What the machine need not even report: a move far from the rack while nothing is engaged and no
// move near it is left for stoppedAt to take again. Apart on any one axis is enough, whichever
// axis told the previous move apart.
TEST(LinearRack, OnlyAFarMoveWithNothingToTakeAgainIsIgnored) {
    LinearRack r = rack();
    EXPECT_TRUE(r.ignores({0, 300, 0}, {500, 300, 0}));     // apart in Y
    EXPECT_TRUE(r.ignores({-200, 0, -80}, {-100, 0, -80})); // in X only
    EXPECT_TRUE(r.ignores({0, 0, 200}, {300, 0, 100}));     // in Z only
    EXPECT_TRUE(r.ignores({0, 300, 0}, {0, 300, 0}));       // standing still far away
    EXPECT_FALSE(r.ignores({0, 0, -70}, {200, 0, -70}));    // along the row of pockets
    EXPECT_FALSE(r.ignores({50, 60, -80}, {50, 5, -80}));   // into the fork of pocket 1
    EXPECT_FALSE(path(r, {{50, 5, 0}, {50, 5, -45}}));      // down over pocket 1, above the tool in it
    EXPECT_FALSE(r.ignores({0, 300, 0}, {500, 300, 0}));    // a stop now must not take that move again
    EXPECT_TRUE(r.passesFar({0, 300, 0}, {500, 300, 0}));   // the rack forgets it
    EXPECT_TRUE(r.ignores({0, 300, 0}, {500, 300, 0}));
    EXPECT_FALSE(path(r, {{0, 300, 0}, {50, 60, -80}, {50, 5, -80}})); // T1 into pocket 1: the fork holds it
    EXPECT_FALSE(r.ignores({0, 300, 0}, {500, 300, 0}));
}
