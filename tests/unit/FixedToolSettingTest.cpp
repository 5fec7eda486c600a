// 固定对刀 with the M350 manual's numbers (setter X Y Z 555.269 / 66.381 / -53.677, 3 passes from
// 250 mm/min, back 50 mm) on the default machine, whose world puts the setter's top at -120: T3
// (58.695 mm long) trips it at machine Z -61.305. Expected values are worked out by hand here.
#include "ToolSettingSupport.h"

#include "core/machine/InputFault.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

constexpr double kT3Trip = -120 + 58.695; // -61.305

controller::RunSettings withTool(int tool) {
    controller::RunSettings settings;
    settings.tool = tool;
    return settings;
}

config::MachineConfig manualMachine() {
    auto cfg = bundledMachine();
    useManualSetter(cfg);
    return cfg;
}

TEST(FixedToolSetting, ModeTwoStoresWhereTheToolTripsTheSetter) {
    auto cfg = manualMachine();
    cfg.parameters.set(932, 0); // T3 never set
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), withTool(3));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(1432), kT3Trip, 1e-9);
    EXPECT_EQ(r.number(1508), 0.0); // only the first setting sets #1508
    // over the setter; up off it after the third pass, a 1 mm run-up, then back 50 (param 140)
    EXPECT_NEAR(r.report.machine(0), 555.269, 1e-9);
    EXPECT_NEAR(r.report.machine(1), 66.381, 1e-9);
    EXPECT_NEAR(r.report.machine(2), kT3Trip + 1 + 50, 1e-9);
    const std::vector<std::string> expected{"固定对刀: 移到对刀仪...", "对刀信号搜索中 1/3...", "对刀信号搜索中 2/3...",
                                            "对刀信号搜索中 3/3...", "对刀完成!"};
    EXPECT_EQ(r.report.messages, expected);
}

TEST(FixedToolSetting, ASlowSignalShowsThePassesHalvingTheirSpeedAndTheAverage) {
    // IN12 heard 10 ms late: each pass runs on by its feed x 10 ms below the trip height, at 250,
    // 125 and 62.5 mm/min: 0.041667, 0.020833, 0.010417 mm; their spread 0.03125 is within 0.05
    auto cfg = manualMachine();
    auto settings = withTool(3);
    settings.inputFaults[12] = machine::InputFault::delayed(0.01);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    EXPECT_RUN_OK(r);
    const double overrun = (250.0 + 125.0 + 62.5) / 60.0 * 0.01 / 3.0; // 0.024306
    EXPECT_NEAR(r.number(1432), kT3Trip - overrun, 1e-9);
    // the last release is heard 62.5 mm/min x 10 ms above the trip height
    EXPECT_NEAR(r.report.machine(2), kT3Trip + 62.5 / 60.0 * 0.01 + 1 + 50, 1e-9);
}

TEST(FixedToolSetting, MorePassesHalveFurther) {
    auto cfg = manualMachine();
    cfg.parameters.set(131, 5);
    cfg.parameters.set(132, 400);
    auto settings = withTool(3);
    settings.inputFaults[12] = machine::InputFault::delayed(0.002);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    EXPECT_RUN_OK(r);
    const double overrun = (400.0 + 200 + 100 + 50 + 25) / 60.0 * 0.002 / 5.0;
    EXPECT_NEAR(r.number(1432), kT3Trip - overrun, 1e-9);
    EXPECT_EQ(r.report.messages[r.report.messages.size() - 2], "对刀信号搜索中 5/5...");
}

TEST(FixedToolSetting, FirstSettingKeepsTheWorkZeroWhereItWas) {
    // The operator zeroed Z on the work with T3 not yet set (param 932 = 0): G54 Z = -12.5 is the
    // nose's machine Z there. The first setting stores T3's trip and moves G54 Z by the difference
    // (-12.5 + 0 - (-61.305) = 48.805), so work Z at any height is what it was: A = B - C - D.
    auto cfg = manualMachine();
    cfg.parameters.set(932, 0);
    ProgramRun r = runProgram(cfg,
                              lines({"G53 Z-20", "#100 = #852", "#1502 = 1", "M98 P502", "G53 Z-20",
                                     "#101 = #852", "M30"}),
                              withTool(3));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(1432), kT3Trip, 1e-9);
    EXPECT_NEAR(r.number(807), -12.5 + 0 - kT3Trip, 1e-9);
    EXPECT_EQ(r.number(1508), 1.0);
    EXPECT_NEAR(r.number(101), r.number(100), 1e-9); // work Z at machine Z -20, before and after
    EXPECT_NEAR(r.number(100), -20 - (-12.5), 1e-9);
}

TEST(FixedToolSetting, FirstSettingOfASetToolLeavesTheWorkZeroWhereItWas) {
    // T3 already set 0.2 mm off: the new trip replaces it and G54 Z absorbs the difference
    auto cfg = manualMachine();
    cfg.parameters.set(932, kT3Trip + 0.2);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 1", "M98 P502", "G53 Z-20", "M30"}), withTool(3));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(807), -12.5 + 0.2, 1e-9);
    EXPECT_NEAR(r.report.work(2), -20 - (-12.5) - (kT3Trip + 0.2), 1e-9); // as before the setting
}

// Every move the machine makes, as the panel's path view is told of it.
struct MoveRecorder : machine::MachineObserver {
    struct Move {
        bool rapid;
        machine::Axes from;
        machine::Axes to;
        double feed;
    };
    std::vector<Move> moves;
    void onMachineEvent(const machine::MachineEvent& e) override {
        if (e.type == machine::MachineEvent::Type::Rapid || e.type == machine::MachineEvent::Type::Feed) {
            moves.push_back({e.type == machine::MachineEvent::Type::Rapid, e.from, e.to, e.feed});
        }
    }
};

TEST(FixedToolSetting, SafeHeightThenOverTheSetterThenDownPassesAtHalvingSpeeds) {
    auto cfg = manualMachine();
    cfg.parameters.set(141, -5);
    auto settings = withTool(3);
    MoveRecorder recorder;
    settings.observer = &recorder;
    ProgramRun r = runProgram(cfg, lines({"G53 X100 Y100 Z-70", "#1502 = 2", "M98 P502", "M30"}), settings);
    EXPECT_RUN_OK(r);
    const auto& m = recorder.moves;
    ASSERT_GE(m.size(), 4u);
    auto at = [](const machine::Axes& p, double x, double y, double z) {
        return std::abs(p(0) - x) < 1e-9 && std::abs(p(1) - y) < 1e-9 && std::abs(p(2) - z) < 1e-9;
    };
    EXPECT_TRUE(m[1].rapid && at(m[1].to, 100, 100, -5));              // straight up to param 141
    EXPECT_TRUE(m[2].rapid && at(m[2].to, 555.269, 66.381, -5));       // over the setter
    EXPECT_TRUE(m[3].rapid && at(m[3].to, 555.269, 66.381, -53.677));  // down to param 137
    std::vector<double> downFeeds;
    for (const auto& move : m) {
        if (!move.rapid && move.to(2) < move.from(2) - 1e-9) {
            downFeeds.push_back(move.feed);
            EXPECT_NEAR(move.to(2), kT3Trip, 1e-9);
        }
    }
    EXPECT_EQ(downFeeds, (std::vector<double>{250, 125, 62.5}));
    EXPECT_TRUE(m.back().rapid && at(m.back().to, 555.269, 66.381, kT3Trip + 1 + 50)); // back 50
}

TEST(FixedToolSetting, TheBackOffStopsAtTheSafeHeight) {
    // T3 trips at -61.305: back 50 from -60.305 would reach -10.305, above param 141 = -20
    auto cfg = manualMachine();
    cfg.parameters.set(141, -20);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), withTool(3));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.report.machine(2), -20, 1e-9);
}

TEST(FixedToolSetting, AVirtualToolKeepsItsOffsetInParams973On) {
    // T17 is virtual on the default machine (capacity 16, param 803): its offset is param 973
    auto cfg = manualMachine();
    cfg.toolLengths.resize(17, 0.0);
    cfg.toolLengths[16] = 61.0;
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), withTool(17));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(1473), -120 + 61.0, 1e-9);
    EXPECT_EQ(r.number(1446), 0.0); // param 946 is no tool's
}

// --- alarms ---

TEST(FixedToolSettingAlarm, NoToolInTheSpindle) {
    ProgramRun r = runProgram(manualMachine(), lines({"#1502 = 2", "M98 P502", "M30"}), withTool(0));
    expectMacroAlarm(r, 1, "当前刀位空刀不能对刀!");
    EXPECT_NEAR(r.report.machine(2), 0.0, 1e-9); // nothing moved
}

TEST(FixedToolSettingAlarm, AxesNotHomed) {
    auto settings = withTool(3);
    settings.homed = false;
    ProgramRun r = runProgram(manualMachine(), lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    expectMacroAlarm(r, 2, "X,Y,Z轴机械未全部归零! home X, Y and Z before setting a tool");
}

TEST(FixedToolSettingAlarm, AToolWithoutAZOffset) {
    ProgramRun r = runProgram(manualMachine(), lines({"#1300 = 40", "#1502 = 2", "M98 P502", "M30"}));
    expectMacroAlarm(r, 3, "刀具号超出范围! the tool is neither in the magazine nor a virtual tool: params 801, 803");
}

TEST(FixedToolSettingAlarm, TheSetterSwitchedOff) {
    auto cfg = manualMachine();
    cfg.parameters.set(130, 0);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), withTool(3));
    expectMacroAlarm(r, 4, "固定对刀仪无效! the fixed setter is switched off: param 130");
    EXPECT_NEAR(r.number(1432), -61.305, 1e-9); // as params.toml has it
}

TEST(FixedToolSettingAlarm, NoModeOtherThanZeroOneTwo) {
    ProgramRun r = runProgram(manualMachine(), lines({"#1502 = 3", "M98 P502", "M30"}), withTool(3));
    expectMacroAlarm(r, 7, "对刀方式错误! #1502 must be 0 floating, 1 first fixed or 2 fixed");
}

TEST(FixedToolSettingAlarm, TheSetterNeverTrips) {
    // its cable is broken: IN12 stays 0; the search ends 200 mm below where it began
    auto cfg = manualMachine();
    cfg.parameters.set(932, 0);
    auto settings = withTool(3);
    settings.heldInputs[12] = 0;
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    ASSERT_EQ(r.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SkipNotTriggered);
    EXPECT_EQ(r.report.alarm->file, "slib-probe.nc");
    EXPECT_NEAR(r.report.machine(2), -53.677 - 200, 1e-9);
    EXPECT_EQ(r.number(1432), 0.0);
}

TEST(FixedToolSettingAlarm, TheSearchStopsAtTheZSoftLimit) {
    auto cfg = manualMachine();
    cfg.parameters.set(155, 1);
    for (int n : {161, 162, 163}) {
        cfg.parameters.set(n, -9999);
    }
    for (int n : {166, 167, 168}) {
        cfg.parameters.set(n, 9999);
    }
    cfg.parameters.set(163, -100);
    auto settings = withTool(3);
    settings.heldInputs[12] = 0;
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    ASSERT_EQ(r.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SkipNotTriggered);
    EXPECT_NEAR(r.report.machine(2), -100, 1e-9);
}

TEST(FixedToolSettingAlarm, PassesThatDisagree) {
    // IN12 heard 50 ms late: the passes stop 0.208, 0.104 and 0.052 mm below the trip height, a
    // spread of 0.156 mm against the macro's 0.05; the tool's offset stays as it was
    auto cfg = manualMachine();
    auto settings = withTool(3);
    settings.inputFaults[12] = machine::InputFault::delayed(0.05);
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    expectMacroAlarm(r, 6, "对刀误差过大! the passes disagree beyond the tolerance: see the message before this alarm");
    EXPECT_EQ(r.report.messages.back(), "对刀误差 0.156 mm, 允许 0.050 mm");
    EXPECT_NEAR(r.number(1510), (250.0 - 62.5) / 60.0 * 0.05, 1e-9);
    EXPECT_NEAR(r.number(1432), -61.305, 1e-9);
}

TEST(FixedToolSettingAlarm, AToolThatStartsOnTheSetterLeavesItFirst) {
    // the manual's Z start is exactly T1's trip height: the switch is closed when probing begins
    auto cfg = manualMachine();
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}), withTool(1));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(1430), -53.677, 1e-9);
}

} // namespace
