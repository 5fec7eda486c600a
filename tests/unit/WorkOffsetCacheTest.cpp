// The modal interpreter keeps the total work offset from block to block. Each program first moves
// (so the offset is computed and kept), then changes one thing the offset is made of, then moves to
// the same work position again: the machine position must follow every change.
#include "RunProgram.h"

#include "core/interp/WorkOffsets.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(WorkOffsetCacheM350, OffsetWritesAndTheWorkSystemMoveTheNextBlock) {
    // #805 / #810: G54 X / G55 X; #578 is parameter 78, the work system in use (1 = G54)
    auto run = runM350(lines({"G90 G1 X0 F1000", "#805 = 10", "#810 = 20", "X0", "#100 = #880", "G55 X0",
                              "#101 = #880", "#578 = 1", "X0", "#102 = #880", "G92 X5", "X0", "#103 = #880",
                              "G52 X3", "X0", "#104 = #880", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 10); // a variable write to the active system's offset
    EXPECT_DOUBLE_EQ(run.number(101), 20); // G55 selected by its code
    EXPECT_DOUBLE_EQ(run.number(102), 10); // G54 selected by parameter 78
    EXPECT_DOUBLE_EQ(run.number(103), 5);  // G92 at machine 10 reading 5: G54 X becomes 5
    EXPECT_DOUBLE_EQ(run.number(104), 8);  // plus G52's 3
}

TEST(WorkOffsetCacheM350, TheToolInTheSpindleAndItsZOffsetMoveTheNextBlock) {
    // #1300 is parameter 800 (the tool in the spindle); #1430, #1431: tools 1 and 2's Z offsets
    auto run = runM350(lines({"#1430 = -50", "#1431 = -30", "G90 G1 Z0 F1000", "#100 = #882", "#1300 = 1", "Z0",
                              "#101 = #882", "#1430 = -40", "Z0", "#102 = #882", "#1300 = 2", "Z0", "#103 = #882",
                              "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 0);   // no tool: no Z offset
    EXPECT_DOUBLE_EQ(run.number(101), -50); // tool 1 put in the spindle
    EXPECT_DOUBLE_EQ(run.number(102), -40); // tool 1's offset written
    EXPECT_DOUBLE_EQ(run.number(103), -30); // tool 2 put in the spindle
}

TEST(WorkOffsetCacheFanuc, G10G92AndToolLengthMoveTheNextBlock) {
    auto run = runFanuc(lines({"G90 G1 X0 Z0 F1000", "G10 L2 P1 X100", "X0", "#100 = #5021", "G92 X40", "X0",
                               "#101 = #5021", "G10 L11 P1 R2", "G43 H1 Z0", "#102 = #5023", "G20 Z0",
                               "#103 = #5023", "G21 G49 Z0", "#104 = #5023", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 100);  // G10 L2 wrote G54 X
    EXPECT_DOUBLE_EQ(run.number(101), 60);   // at machine 100 work X reads 40: G92 shifts by 60 - 100
    EXPECT_DOUBLE_EQ(run.number(102), 2);    // G43 H1: offset 1 is 2
    EXPECT_DOUBLE_EQ(run.number(103), 50.8); // under G20 the offset is 2 inches
    EXPECT_DOUBLE_EQ(run.number(104), 0);    // G49 cancels it
}

TEST(WorkOffsetCacheFanuc, AnOffsetWrittenBetweenRunsMovesTheNextRun) {
    auto run = runFanuc(lines({"G90 G1 X0 F1000", "M30"}));
    EXPECT_RUN_OK(run);
    run.controller->setWorkPosition(0, 25.0); // machine X 0 now reads work X 25
    run.report = run.controller->run();
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.report.machine(0), -25);
}

// 断点加工 saves the offsets and puts them back: a version that went back with them could name
// two different sets of offsets.
TEST(WorkOffsets, AVersionNamesOneSetOfOffsetsAlsoAfterARestore) {
    interp::WorkOffsets offsets;
    const interp::WorkOffsets saved = offsets;
    offsets.set(1, 0, 10.0);
    const auto withTen = offsets.version();
    offsets = saved;
    offsets.set(1, 0, 20.0);
    EXPECT_NE(offsets.version(), withTen);
    EXPECT_DOUBLE_EQ(offsets.get(1, 0), 20.0);
}

} // namespace
