// What counts as cutting time for a minutes group, with hand-computed times: feed moves, arcs and
// a canned cycle's feed count; rapids, dwells, a feed hold and the tool change program's own moves
// (the M350's O20000, which the T word runs) do not. The panel has no machine lock, Z lock, dry
// run or single block, so there is no such time to leave out.
#include "ToolLifeFixture.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(ToolLifeCuttingTime, FeedArcAndDrillFeedCountRapidsAndDwellsDoNot) {
    config::MachineConfig config = fanucWithGroups();
    // rapids as slow as the feed: counting them would add whole units
    config.parameters.set(param::kRapidSpeed, 600);
    // At F600 (10 mm/s): G1 over 72 mm 7.2 s; the half circle of radius 10, 10 pi mm = 3.1416 s; G81
    // feeds from R2 to Z-20, 22 mm = 2.2 s. 12.54 s of cutting = 3 whole 4 s units. Without the arc or
    // the drill it would be 2; with the 30 s dwell 10 or more; with the rapids (Z10, X50, X150, the
    // drill's XY, R and return: over 30 s at 600 mm/min) far more.
    ProgramRun run = runProgram(config, lines({"T102 M06", "G0 Z10", "G0 X50", "G1 X122 F600", "G4 X30", "G0 X150",
                                               "G2 X170 Y0 I10 J0", "G81 X0 Y0 Z-20 R2 F600", "G80", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 2, 21), 3);
    EXPECT_GT(run.report.simTime, 40.0); // the run itself took far longer
}

TEST(ToolLifeCuttingTime, TheM350TWordChangesTheToolButItsMovesDoNotCount) {
    // The M350 machine: T101 selects group 1 (a simulator extra there) and runs O20000, whose Z
    // moves to and from the pocket are G01 at the magazine's feed; they carry the tool, not cut.
    config::MachineConfig config = bundledMachine();
    config.toolLife.putGroup(group(1, 1, tools::LifeKind::Minutes, {{3, 0, 0, 0}, {4, 0, 0, 0}}));
    ProgramRun run = runProgram(config, lines({"T101", "G91 G1 X100 F600", "G90", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.controller->parameter(param::kCurrentTool), 3);
    EXPECT_EQ(used(run, 1, 3), 2); // the 10 s cut: 2 units
    EXPECT_EQ(used(run, 1, 4), 0);
}

TEST(ToolLifeCuttingTime, AHoldThenResetCountsOnlyTheCutBeforeTheHold) {
    ProgramRun run = loadProgram(fanucWithGroups(), lines({"T102 M06", "G1 X200 F600", "M30"}));
    ASSERT_TRUE(run.loaded);
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(9.0); // 8.9 s or so of the 20 s cut
    c.hold();
    c.advance(30.0);
    c.reset(); // the rest of the cut never happens
    EXPECT_EQ(c.toolLife().manager().data().group(2)->tools[0].used, 2);
}

} // namespace
