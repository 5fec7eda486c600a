// Tool breakage detection on the bundled FANUC machine with a TS27R setter (fanuc-ts27r): the
// setter calibration O9855 and the check G65 P9858, the spindle load monitor, and one broken tool
// found by both. Expected values are computed by hand from machine.toml: stylus centre X400 Y-50,
// radius 6.35, top -450; T1 120 mm long, 10 mm wide; T97 336.489 x 10.016; stock top -480.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

controller::RunSettings withTool(int tool, std::vector<machine::ToolBreak> breaks = {}) {
    controller::RunSettings settings;
    settings.tool = tool;
    settings.toolBreaks = std::move(breaks);
    return settings;
}

const std::string kCheck = lines({"G91 G28 Z0", "G65 P9858 T1 H0.5", "M30"});
// T1 slots 2 mm deep along X at 600 mm/min and 6000 rpm for 30 s (33.3 % load), from about 5.4 s
const std::string kCut = lines({"G90 G49", "S6000 M03", "G00 X-150 Y0", "G00 Z-355", "G01 Z-362 F300",
                                "G01 X150 F600", "G00 Z0", "M05", "M30"});

TEST(BreakageBySetter, CalibrationFindsTheStylusAsTheArticleStoresIt) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"),
                          lines({"G90 G49", "G53 G00 X400 Y-50", "G53 G00 Z-103.511", "G65 P9855 T97 R10.016 D12.7",
                                 "M30"}),
                          withTool(97));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    // the side contacts: centre +- (6.35 + 10.016 / 2); the top: nose at contact - 336.489
    EXPECT_NEAR(run.number(522), 411.358, 1e-9);
    EXPECT_NEAR(run.number(521), 388.642, 1e-9);
    EXPECT_NEAR(run.number(523), -38.642, 1e-9);
    EXPECT_NEAR(run.number(524), -61.358, 1e-9);
    EXPECT_NEAR(run.number(520), -450.0, 1e-9);
}

TEST(BreakageBySetter, AnIntactToolPassesAndItsLengthIsReported) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), kCheck, withTool(1));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(135), 120.0, 1e-9);
    EXPECT_NEAR(run.number(136), 0.0, 1e-9);
}

TEST(BreakageBySetter, ABrokenToolIsAMacroAlarmSayingHowShort) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), kCheck, withTool(1, {{1, 0.62, 0.0}}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::MacroAlarm);
    EXPECT_EQ(run.report.alarm->message, "macro alarm 3094: tool 1 broken: 0.62 mm short, tolerance 0.5");
    EXPECT_NEAR(run.number(135), 119.38, 1e-9); // where G31 tripped: 0.62 mm lower
}

TEST(BreakageBySetter, WithinToleranceIsNoAlarm) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), lines({"G65 P9858 T1 H0.7", "M30"}),
                          withTool(1, {{1, 0.62, 0.0}}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(136), -0.62, 1e-9);
}

TEST(BreakageBySetter, AnUncalibratedSetterIsRefused) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), lines({"#520 = #0", "G65 P9858 T1 H0.5", "M30"}),
                          withTool(1));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "macro alarm 3092: the setter is not calibrated: run O9855, #520-#524 are empty");
}

TEST(BreakageBySetter, WithDAnEndMillIsMeasuredUnderItsEdge) {
    // T2: 95.5 long, 16 wide. D16 puts its axis 8 mm beside the stylus centre (X400 + 8), where
    // its edge stands over the stylus; the length is the same as measured at the centre.
    auto run = runProgram(bundledMachine("fanuc-ts27r"),
                          lines({"G91 G28 Z0", "G65 P9858 T2 H0.5 D16", "#100 = #5021", "#101 = #5022", "M30"}),
                          withTool(2));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(100), 408.0, 1e-9);
    EXPECT_NEAR(run.number(101), -50.0, 1e-9);
    EXPECT_NEAR(run.number(135), 95.5, 1e-9);
    EXPECT_NEAR(run.number(136), 0.0, 1e-9);
}

TEST(BreakageBySetter, ATouchOnTheWayToAStartPointStopsTheCalibration) {
    // started beside the stylus 6.5 mm lower than its top (nose -120 < -113.511; over it that
    // rapid would be a crash): the first G31 to the X+ start point touches at once, so its end is
    // not where it was sent
    auto run = runProgram(bundledMachine("fanuc-ts27r"),
                          lines({"G90 G49", "G53 G00 X380 Y-50", "G53 G00 Z-120", "G65 P9855 T97 R10.016 D12.7",
                                 "M30"}),
                          withTool(97));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "macro alarm 3096: the setter was touched on the way to a start point: "
                                         "start with the tool about 10 mm above the stylus centre");
}

TEST(BreakageBySpindleLoad, TheCutReadsItsHandComputedLoadIn1032) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), lines({"G90 G49", "S6000 M03", "G00 X-150 Y0", "G00 Z-355",
                                                              "G01 Z-362 F300", "G01 X150 F600", "#100 = #1032",
                                                              "M30"}),
                          withTool(1));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_EQ(run.number(100), 3329); // 33.3 % -> L 7630 -> 14300 x 7630 / 32767
    const auto& history = run.controller->toolBreakage().spindleLoad().monitor().history();
    ASSERT_FALSE(history.empty());
    EXPECT_DOUBLE_EQ(history.back().percent, 33.29);
    EXPECT_TRUE(history.back().cutting);
}

TEST(BreakageBySpindleLoad, ABreakMidCutStopsTheRunHalfASecondLater) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), kCut, withTool(1, {{1, 0.62, 12.05}}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SpindleLoad);
    EXPECT_EQ(run.report.alarm->line, 6u);
    // the spike (above 60 %) at 12.1-12.3 and the idle 3.29 % after it: 5 samples out from 12.1
    EXPECT_NE(run.report.alarm->message.find("for 5 samples since 12.10 s, now 3.29 % (below)"), std::string::npos)
        << run.alarmText();
    EXPECT_LT(run.report.machine(0), 150.0 - 1.0); // stopped in the cut
    EXPECT_NEAR(run.report.simTime, 12.5 + 10.0 / 500.0, 1e-3); // 10 mm/s braked at 500 mm/s2 (+ a block)
    EXPECT_EQ(run.report.outputs, decltype(run.report.outputs){});     // outputs safe
}

// One scenario, two detections: T1 breaks 0.62 mm in the cut; the load monitor stops the run, and
// the setter check after the reset says how much is missing.
TEST(BreakageScenario, ABrokenToolIsFoundByTheLoadMonitorAndThenByTheSetter) {
    auto run = runProgram(bundledMachine("fanuc-ts27r"), kCut, withTool(1, {{1, 0.62, 12.05}}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SpindleLoad);
    controller::Controller& c = *run.controller;
    c.reset();
    ASSERT_TRUE(c.loadMdi({"G91 G28 Z0", "G65 P9858 T1 H0.5"}));
    controller::RunReport check = c.run();
    ASSERT_EQ(check.status, controller::RunStatus::Alarm);
    EXPECT_EQ(check.alarm->message, "macro alarm 3094: tool 1 broken: 0.62 mm short, tolerance 0.5");
}

} // namespace
