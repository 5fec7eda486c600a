// G31 against the fixed tool setter: where the signal comes, the result variables of both dialects,
// and the alarm when it never comes.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(ProbeM350, G31StopsWhereTheToolTripsTheSetter) {
    controller::RunSettings settings;
    settings.tool = 2;
    auto run = runProgram(bundledMachine(), lines({"G53 Z-20", "G53 X555.269 Y66.381", "G91 G31 Z-100 F200 P12 L1",
                                                   "#100 = #1922", "#101 = #1927", "#102 = #1920", "#103 = #882",
                                                   "M30"}),
                          settings);
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 2);          // Z hit
    EXPECT_NEAR(run.number(101), -48.12, 1e-9);    // T2 trips where param 931 says
    EXPECT_DOUBLE_EQ(run.number(102), 0);          // X did not probe
    EXPECT_NEAR(run.number(103), -48.12, 1e-9);    // and the machine stopped there
}

// `#1922=0 ;clear probe status before retract`, as probing macros write it; the next G31 sets it
// again. The trigger position stays the probe's own.
TEST(ProbeM350, AMacroClearsTheResultAndTheNextProbeSetsItAgain) {
    controller::RunSettings settings;
    settings.tool = 2;
    auto run = runProgram(bundledMachine(), lines({"G53 Z-20", "G53 X555.269 Y66.381", "G91 G31 Z-100 F200 P12 L1",
                                                   "#1922=0 ;clear probe status before retract", "#100 = #1922",
                                                   "#101 = #1927", "G91 G00 Z2", "#102 = #1922",
                                                   "G91 G31 Z-5 F100 P12 L1", "#103 = #1922", "#1920 = 7",
                                                   "#104 = #1920", "M30"}),
                          settings);
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 0);
    EXPECT_NEAR(run.number(101), -48.12, 1e-9); // the position is not cleared
    EXPECT_DOUBLE_EQ(run.number(102), 0);       // a move is no probe
    EXPECT_DOUBLE_EQ(run.number(103), 2);
    EXPECT_DOUBLE_EQ(run.number(104), 7);

    auto positions = runProgram(bundledMachine(), lines({"#1927 = 0", "M30"}));
    ASSERT_EQ(positions.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(positions.report.alarm->code, AlarmCode::ReadOnlyVariable);
}

TEST(ProbeM350, G31AwayFromTheSetterIsAnAlarmNamingTheInput) {
    auto run = runProgram(bundledMachine(), lines({"G53 Z-20", "G53 X100 Y66.381", "G91 G31 Z-100 F200 P12 L1",
                                                   "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SkipNotTriggered);
    EXPECT_EQ(run.report.alarm->line, 3u);
    EXPECT_NE(run.report.alarm->message.find("IN12 never became 1"), std::string::npos) << run.alarmText();
}

// A FANUC machine whose skip signal is the setter's switch on IN12, the setter at X50 Y20 with its
// top at -200 for a zero-length tool; T1 (100 mm) in the spindle.
ProgramRun runWithSetter(const std::string& program) {
    auto cfg = fanucMachine();
    cfg.parameters.set(575, 12);
    cfg.parameters.set(576, 1);
    cfg.parameters.set(577, 1);
    cfg.parameters.set(135, 50);
    cfg.parameters.set(136, 20);
    cfg.setterTop = -200;
    cfg.toolLengths = {100.0};
    controller::RunSettings settings;
    settings.tool = 1;
    return runProgram(cfg, program, settings);
}

TEST(ProbeFanuc, SkipSignalGivesTheWorkPositionIn5061To5065) {
    auto run = runWithSetter(lines({"G10 L2 P1 Z-50", "G54 G90 G00 X50 Y20 Z0", "G31 Z-200 F100", "#100 = #5063",
                                      "#101 = #5023", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(101), -100.0, 1e-9); // machine: top -200 + length 100
    EXPECT_NEAR(run.number(100), -50.0, 1e-9);  // work: -100 - G54 Z (-50)
}

TEST(ProbeFanuc, WithoutTheSignalG31EndsAtItsEndPointWhich5061Holds) {
    // far from the setter (X 0): nothing stops the move
    auto run = runWithSetter(lines({"G10 L2 P1 Z-50", "G54 G90 G00 X0 Y20 Z0", "G31 X10 Z-120 F100",
                                    "#100 = #5061", "#101 = #5063", "#102 = #5023", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(100), 10.0, 1e-9);
    EXPECT_NEAR(run.number(101), -120.0, 1e-9);
    EXPECT_NEAR(run.number(102), -170.0, 1e-9); // machine: work -120 + G54 Z -50
}

} // namespace
