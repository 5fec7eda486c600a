// G10, G43/G44/G49, G52, G92, G28/G30, soft limits and arcs, checked through the variables a macro
// reads and the time the moves take.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace m350;
using namespace m350::test;

TEST(PositioningFanuc, G10L2WritesTheWorkOffsetAbsoluteOrIncremental) {
    auto run = runFanuc(lines({"G90 G10 L2 P1 X100 Y50 Z-30", "#100 = #5221", "#101 = #5223",
                               "G91 G10 L2 P1 X5", "#102 = #5221", "G90 G10 L2 P0 Z-1", "#103 = #5203",
                               "G54 G00 X0 Y0 Z0", "#104 = #5021", "#105 = #5023", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 100);
    EXPECT_DOUBLE_EQ(run.number(101), -30);
    EXPECT_DOUBLE_EQ(run.number(102), 105);
    EXPECT_DOUBLE_EQ(run.number(103), -1);
    EXPECT_DOUBLE_EQ(run.number(104), 105); // machine X = work 0 + G54 105
    EXPECT_DOUBLE_EQ(run.number(105), -31); // machine Z = 0 + G54 -30 + external -1
}

// FANUC's L20 is the additional work systems' L2 (G54.1 Pn), not LinuxCNC's "set so the tool
// reads this" (which a FANUC does not have).
TEST(PositioningFanuc, G10L20WritesAnAdditionalSystemsOffsetAbsoluteOrIncremental) {
    auto run = runFanuc(lines({"G53 X40 Y10", "G90 G10 L20 P2 X7 Y5", "#100 = #7021", "#101 = #7022",
                               "G91 G10 L20 P2 X1", "G90", "#102 = #7021", "#103 = #5041", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 7);
    EXPECT_DOUBLE_EQ(run.number(101), 5);
    EXPECT_DOUBLE_EQ(run.number(102), 8);
    EXPECT_DOUBLE_EQ(run.number(103), 40); // G54 still active: writing P2 moved nothing
}

TEST(PositioningFanuc, G43AddsAndG44SubtractsTheToolLengthG49Cancels) {
    auto run = runFanuc(lines({"G10 L11 P3 R125.5", "#100 = #2003", "G90 G43 H3 G00 Z10", "#101 = #5023",
                               "#102 = #5043", "G44 H3 Z10", "#103 = #5023", "G49 Z10", "#104 = #5023",
                               "#105 = #4008", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 125.5);
    EXPECT_DOUBLE_EQ(run.number(101), 135.5);
    EXPECT_DOUBLE_EQ(run.number(102), 10);
    EXPECT_DOUBLE_EQ(run.number(103), -115.5);
    EXPECT_DOUBLE_EQ(run.number(104), 10);
    EXPECT_DOUBLE_EQ(run.number(105), 49);
}

TEST(PositioningM350, G43IsRefusedBecauseToolOffsetsApplyByThemselves) {
    auto run = runM350(lines({"G43 H1 Z0", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(run.report.alarm->message.find("params 930-945"), std::string::npos) << run.alarmText();
}

TEST(Positioning, G52ShiftsALocalSystemAndG52ZeroEndsIt) {
    auto run = runFanuc(lines({"G52 X10 Y20", "G90 G00 X0 Y0", "#100 = #5021", "#101 = #5022", "G52 X0 Y0",
                               "G00 X0 Y0", "#102 = #5021", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 10);
    EXPECT_DOUBLE_EQ(run.number(101), 20);
    EXPECT_DOUBLE_EQ(run.number(102), 0);
}

TEST(Positioning, G92GivesTheCurrentPositionNewWorkCoordinates) {
    auto run = runFanuc(lines({"G00 X30", "G92 X0", "#100 = #5041", "G00 X5", "#101 = #5021", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 0);
    EXPECT_DOUBLE_EQ(run.number(101), 35);
}

TEST(PositioningM350, G28GoesThroughTheIntermediatePointToParams122To126) {
    auto cfg = m350Machine();
    cfg.parameters.set(122, 5);
    cfg.parameters.set(124, -5);
    auto run = runProgram(std::move(cfg), lines({"G53 X100 Z-50", "G90 G28 X0 Z0", "#100 = #880", "#101 = #882",
                                                 "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 5);
    EXPECT_DOUBLE_EQ(run.number(101), -5);
}

TEST(PositioningM350, SoftLimitStopsTheMoveBeforeItStarts) {
    auto cfg = m350Machine();
    cfg.parameters.set(155, 1);
    for (int axis = 0; axis < 5; ++axis) {
        cfg.parameters.set(161 + axis, -500);
        cfg.parameters.set(166 + axis, 500);
    }
    auto run = runProgram(std::move(cfg), lines({"G53 X100", "G53 X600", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SoftLimit);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_NE(run.report.alarm->message.find("X+ soft limit"), std::string::npos) << run.alarmText();
    EXPECT_NE(run.report.alarm->message.find("parameter 166"), std::string::npos) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.report.machine(0), 100.0); // never moved
}

TEST(PositioningM350, ArcTakesTheTimeOfItsPathNotOfItsChord) {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 1e9); // ramps negligible: time = length / speed
    // from (0,0) about (10,0) counterclockwise to (10,-10): a quarter of radius 10, 15.708 mm at 10 mm/s
    auto run = runProgram(std::move(cfg), lines({"G17 G90 G03 X10 Y-10 I10 J0 F600", "#100 = #880", "#101 = #881",
                                                 "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(100), 10.0, 1e-9);
    EXPECT_NEAR(run.number(101), -10.0, 1e-9);
    double arcSeconds = (std::numbers::pi * 10.0 / 2.0) / 10.0;
    EXPECT_NEAR(run.report.simTime, arcSeconds + 4 * 1e-4, 1e-6);
}

TEST(PositioningM350, ArcWhoseEndIsOffTheCircleIsRefused) {
    auto run = runM350(lines({"G02 X0 Y-10 I-10 J0 F600", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->line, 1u);
    EXPECT_NE(run.report.alarm->message.find("not on the circle"), std::string::npos) << run.alarmText();
}

TEST(PositioningM350, M30CountsRunsAndPiecesInParams201And202) {
    auto run = runM350(lines({"#701 = 9", "G04 P1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(701), 10);
    EXPECT_DOUBLE_EQ(run.number(702), 1);
}

} // namespace
