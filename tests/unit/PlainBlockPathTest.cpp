// The short ways a plain block takes through the executor and the interpreter: the words indexed
// by letter once (EvaluatedBlock), a block of one motion code setting its group without the G code
// loop, and the work offset kept while the parameters' version stands. Each test breaks the
// assumption the shortcut rests on.
#include "RunProgram.h"

#include "core/params/ParameterTable.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(PlainBlockPath, WordsTakenOutForACallLeaveTheMoveItsOwnWords) {
    // M99 is taken out before the block goes on: the words after it move up, so the index made
    // while evaluating (X at 3, Y at 4) must be made again
    auto run = runM350(lines({"M98 P100", "M30", "O100", "M99 G90 G1 X5 Y7 F100"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.report.work(0), 5);
    EXPECT_DOUBLE_EQ(run.report.work(1), 7);
}

TEST(PlainBlockPath, ALetterTwiceIsStillRefusedAfterACallWasTakenOut) {
    auto run = runM350(lines({"M98 P100", "M30", "O100", "M99 G1 X5 X6 F100"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(run.report.alarm->message.find("X appears twice"), std::string::npos) << run.alarmText();
}

TEST(PlainBlockPath, AMotionCodeAloneEndsTheCannedCycle) {
    // #4001 / #4009: the motion and canned cycle groups. Under a cycle left active, G1 X10 would
    // drill a hole at X10 instead of moving there.
    auto run = runFanuc(lines({"G90 G0 Z10", "G98 G81 X0 Y0 Z-5 R2 F100", "G1 X10", "#100 = #4001", "#101 = #4009", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 1);
    EXPECT_DOUBLE_EQ(run.number(101), 80);
    EXPECT_DOUBLE_EQ(run.report.work(0), 10);
    EXPECT_DOUBLE_EQ(run.report.work(2), 10); // the initial level, not a hole's bottom
}

TEST(PlainBlockPath, ParameterTableVersionMovesOnWithEveryWriteAndRestore) {
    params::ParameterTable table;
    const params::ParameterTable saved = table;
    const std::uint64_t start = table.version();
    table.set(800, 3);
    const std::uint64_t written = table.version();
    EXPECT_GT(written, start);
    table = saved; // back to the old values: a reader's kept result is stale all the same
    EXPECT_GT(table.version(), written);
    EXPECT_DOUBLE_EQ(table.get(800), 0);
}

TEST(PlainBlockPath, RestoredParametersMoveTheNextBlock) {
    // #1300 is parameter 800, the tool in the spindle; #1430 tool 1's Z offset. The start-at-line
    // scan restores the parameters by assignment; here a variable write and back stand in for it
    // on the same table, and each must reach the next move.
    auto run = runM350(lines({"#1430 = -50", "G90 G1 Z0 F1000", "#1300 = 1", "Z0", "#100 = #882", "#1300 = 0", "Z0",
                              "#101 = #882", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), -50);
    EXPECT_DOUBLE_EQ(run.number(101), 0);
}

} // namespace
