// What the canned cycles refuse, each with the word it names; the moves themselves are in
// CannedCyclesTest.cpp.
#include "TracedRun.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

struct Expected {
    AlarmCode code;
    std::uint32_t line;
    std::uint32_t column;
    std::string message; // a part of it
};

void expectAlarm(const ProgramRun& run, const Expected& expected) {
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm) << "no alarm";
    const Alarm& alarm = *run.report.alarm;
    EXPECT_EQ(alarmKey(alarm.code), alarmKey(expected.code)) << run.alarmText();
    EXPECT_EQ(alarm.line, expected.line) << run.alarmText();
    EXPECT_EQ(alarm.column, expected.column) << run.alarmText();
    EXPECT_NE(alarm.message.find(expected.message), std::string::npos) << run.alarmText();
}

TEST(CannedCycleAlarms, ZMissingInTheFirstBlock) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G98 G81 X5 R2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::MissingAddress, 2, 5, "G81 needs Z (the hole bottom)"});
}

TEST(CannedCycleAlarms, RMissingInTheFirstBlock) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G81 X5 Z-3 F100", "M30"}));
    expectAlarm(run, {AlarmCode::MissingAddress, 2, 1, "G81 needs R (the level drilling starts from)"});
}

TEST(CannedCycleAlarms, TheDrillingAxisOfG18IsY) {
    auto run = runFanuc(lines({"G00 X0 Y10 Z0", "G18 G81 X5 Z3 R2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::MissingAddress, 2, 5, "G81 needs Y (the hole bottom)"});
}

TEST(CannedCycleAlarms, DrillingDataIsForgottenWhenTheCycleEnds) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G98 G81 X5 Z-3 R2 F100", "G80", "G81 X6", "M30"}));
    expectAlarm(run, {AlarmCode::MissingAddress, 4, 1, "G81 needs Z"});
}

TEST(CannedCycleAlarms, G83WithoutQ) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G83 X5 Z-3 R2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::MissingAddress, 2, 1, "G83 needs Q (peck depth) > 0"});
}

TEST(CannedCycleAlarms, G73WithQZero) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G73 X5 Z-3 R2 Q0 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 15, "G73 needs Q (peck depth) > 0"});
}

TEST(CannedCycleAlarms, QSoSmallThatTheHoleWouldNeverEnd) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G83 X5 Z-100 R0 Q0.001 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 17, "more than 10000 pecks"});
}

TEST(CannedCycleAlarms, FeedZero) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G81 X5 Z-3 R2 F0", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 15, "G81 needs a feed: give F"});
}

TEST(CannedCycleAlarms, NoFeedEverGiven) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G82 X5 Z-3 R2 P100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 1, "G82 needs a feed: give F"});
}

TEST(CannedCycleAlarms, UnderCutterCompensation) {
    auto run =
        runFanuc(lines({"G10 L11 P1 R2", "G00 X0 Y0 Z10", "G41 D1 G01 X10 Y0 F100", "G81 X5 Z-3 R2", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 4, 1, "G81: cutter compensation is on"});
}

TEST(CannedCycleAlarms, G84WithoutTheSpindleTurningForward) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G84 X5 Z-3 R2 F100", "M30"}));
    expectAlarm(run,
                {AlarmCode::InvalidWord, 2, 1, "G84 (right-hand tapping) needs the spindle turning forward"});
}

TEST(CannedCycleAlarms, G74WithTheSpindleTurningForward) {
    auto run = runFanuc(lines({"M03 S500", "G00 X0 Y0 Z10", "G74 X5 Z-3 R2 F100", "M30"}));
    expectAlarm(
        run, {AlarmCode::InvalidWord, 3, 1, "G74 (left-hand tapping) needs the spindle turning in reverse"});
}

TEST(CannedCycleAlarms, AMotionCodeInTheCycleBlock) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G00 G81 X5 Z-3 R2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 5, "would cancel the canned cycle"});
}

TEST(CannedCycleAlarms, BothKAndL) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G91 G81 X5 Z-3 R-8 K2 L2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 23, "as K or as L, not both"});
}

TEST(CannedCycleAlarms, ARepeatCountThatIsNotAWholeNumber) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G91 G81 X5 Z-3 R-8 K1.5 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 20, "a whole number 0-9999"});
}

TEST(CannedCycleAlarms, TheBottomAboveR) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G81 X5 Z3 R2 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 11, "the hole bottom Z lies above R"});
}

TEST(CannedCycleAlarms, ARotaryAxisInTheCycle) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G81 X5 Z-3 R2 A10 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 15, "a rotary axis cannot move in a canned cycle"});
}

TEST(CannedCycleAlarms, NegativeDwell) {
    auto run = runFanuc(lines({"G00 X0 Y0 Z10", "G82 X5 Z-3 R2 P-5 F100", "M30"}));
    expectAlarm(run, {AlarmCode::InvalidWord, 2, 15, "the dwell at the hole bottom cannot be negative"});
}

TEST(CannedCycleAlarms, SoftLimitStopsTheBlockBeforeItsFirstMove) {
    controller::RunSettings settings;
    settings.parameters[param::kSoftLimitsEnabled] = 1;
    for (int axis = 0; axis < 5; ++axis) {
        settings.parameters[param::kSoftLimitNegativeX + axis] = axis == 2 ? -5 : -1000;
        settings.parameters[param::kSoftLimitPositiveX + axis] = 1000;
    }
    auto traced =
        runTraced(fanucMachine(), lines({"G00 X0 Y0 Z10", "G98 G81 X5 Z-8 R2 F100", "M30"}), settings);
    expectAlarm(traced.run, {AlarmCode::SoftLimit, 2, 1, "Z- soft limit"});
    EXPECT_EQ(traced.events, std::vector<std::string>{"rapid X0 Y0 Z10"});
}

} // namespace
