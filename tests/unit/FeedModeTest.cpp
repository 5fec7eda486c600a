// G94 / G95: feed per minute and, on FANUC machines, feed per spindle revolution.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

template <class Machine>
config::MachineConfig quick(Machine make) {
    auto cfg = make();
    cfg.parameters.set(62, 1e9); // G01 acceleration: ramps take no measurable time
    cfg.parameters.set(81, 0);   // no spindle start delay
    return cfg;
}

TEST(FeedMode, G95FeedsPerRevolutionOnFanuc) {
    // 0.1 mm/rev at 1000 rpm = 100 mm/min: 10 mm take 6 s
    ProgramRun r = runProgram(quick(fanucMachine), lines({"M03 S1000", "#1 = #4005", "G95 G01 X10 F0.1",
                                                          "#2 = #4005", "G94 G01 X20 F600", "M30"}));
    ASSERT_EQ(r.report.status, controller::RunStatus::Ok) << r.alarmText();
    EXPECT_EQ(r.number(1), 94.0);
    EXPECT_EQ(r.number(2), 95.0);
    // 6 s for the G95 move, 1 s for 10 mm at 600 mm/min, plus 0.1 ms per block
    EXPECT_NEAR(r.report.simTime, 7.0, 1e-2);
    EXPECT_NEAR(r.report.machine(0), 20.0, 1e-9);
}

TEST(FeedMode, G95FollowsTheSpindleSpeed) {
    ProgramRun slow = runProgram(quick(fanucMachine), lines({"M03 S500", "G95 G01 X10 F0.1", "M30"}));
    EXPECT_NEAR(slow.report.simTime, 12.0, 1e-2); // 50 mm/min
}

TEST(FeedMode, G95WithTheSpindleStoppedIsAnAlarm) {
    ProgramRun r = runProgram(quick(fanucMachine), lines({"G95", "G01 X10 F0.1", "M30"}));
    EXPECT_EQ(r.alarmText(), "invalid_word at " + r.fileName +
                                 ":2:1: G95 feed per revolution with the spindle stopped: start it with M03/M04 S..");
    EXPECT_NEAR(r.report.machine(0), 0.0, 1e-9); // nothing moved
}

TEST(FeedMode, TheM350IgnoresG95) {
    // its manual: G94/G95 do nothing (M29 is for tapping); F stays mm/min
    ProgramRun r = runProgram(quick(m350Machine), lines({"M03 S1000", "G95 G01 X10 F600", "M30"}));
    ASSERT_EQ(r.report.status, controller::RunStatus::Ok) << r.alarmText();
    EXPECT_NEAR(r.report.simTime, 1.0, 1e-2);
}

} // namespace

namespace {

TEST(FeedMode, FInAG20BlockIsInchesPerMinute) {
    // 1 inch at 10 inch/min (254 mm/min): 6 s
    ProgramRun r = runProgram(quick(fanucMachine), lines({"G20 G01 X1. F10.", "M30"}));
    ASSERT_EQ(r.report.status, controller::RunStatus::Ok) << r.alarmText();
    EXPECT_NEAR(r.report.machine(0), 25.4, 1e-9);
    EXPECT_NEAR(r.report.simTime, 6.0, 1e-2);
}

TEST(FeedMode, UnderG20ALinearFourthAxisMovesInInchesARotaryOneInDegrees) {
    ProgramRun linear = runProgram(quick(m350Machine), lines({"G20 G01 A1. F100.", "M30"}));
    EXPECT_NEAR(linear.report.machine(3), 25.4, 1e-9);
    auto rotaryMachine = quick(m350Machine);
    rotaryMachine.parameters.set(449, 1); // 4th axis rotary
    ProgramRun rotary = runProgram(rotaryMachine, lines({"G20 G01 A90. F100.", "M30"}));
    EXPECT_NEAR(rotary.report.machine(3), 90.0, 1e-9);
}

} // namespace
