// The default machine's O502 (对刀 on the fixed setter, slib-probe.nc) and what O20000 does after a
// change with params 805 (set the new tool) and 815 (go back to where the change began).
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(ToolSettingMacro, Param805SetsTheNewToolOnTheSetterAfterTheChange) {
    auto cfg = bundledMachine();
    const double expected = tripHeight(cfg, 2);
    cfg.parameters.set(805, 1);
    cfg.parameters.set(931, 0); // T2 never set
    ProgramRun r = runProgram(cfg, lines({"T2", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(1431), expected, 1e-9);
    EXPECT_EQ(r.report.messages.back(), "对刀完成!");
    // up off the setter after the last pass, a 1 mm run-up, then back by param 140 (50) would end
    // above the safe height (param 141 = 0): it stops there
    EXPECT_GT(expected + 1 + cfg.parameters.get(140), 0.0);
    EXPECT_NEAR(r.report.machine(2), 0.0, 1e-9);
}

TEST(ToolSettingMacro, Param815ReturnsToWhereTheChangeBegan) {
    auto cfg = bundledMachine();
    cfg.parameters.set(815, 1);
    ProgramRun r = runProgram(cfg, lines({"G53 X200 Y150", "T2", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.report.machine(0), 200, 1e-9);
    EXPECT_NEAR(r.report.machine(1), 150, 1e-9);
    EXPECT_NEAR(r.report.machine(2), 0, 1e-9); // at the change height (param 806)
    EXPECT_EQ(r.report.tool, 2);
}

TEST(ToolSettingMacro, FirstFixedProbeKeepsTheWorkZeroRelativeToTheSetter) {
    // T1 not set yet (930 = 0): the operator zeroed Z on the workpiece at machine Z -100, so G54 Z
    // holds -100; the first fixed probe makes it the distance from the setter and sets T1, and the
    // work Z there is still 0 (A = B - C - D)
    auto cfg = bundledMachine();
    cfg.offsets[1][2] = -100;
    cfg.parameters.set(930, 0);
    // (away from the setter first: straight down over it would drive T1 into it)
    ProgramRun r = runProgram(cfg, lines({"#1502 = 1", "M98 P502", "G53 X100 Y100", "G53 Z-100", "M30"}));
    EXPECT_RUN_OK(r);
    const double trip = tripHeight(cfg, 1);
    EXPECT_NEAR(r.number(1430), trip, 1e-9);
    EXPECT_NEAR(r.number(807), -100 - trip, 1e-9);
    EXPECT_NEAR(r.report.work(2), 0, 1e-9);
}

TEST(ToolSettingMacro, NoToolIsAnAlarm) {
    controller::RunSettings settings;
    settings.tool = 0;
    ProgramRun r = runProgram(bundledMachine(), lines({"#1502 = 2", "M98 P502", "M30"}), settings);
    expectMacroAlarm(r, 1, "当前刀位空刀不能对刀!");
}

TEST(ToolSettingMacro, WithoutTheSetterInputIsAnAlarm) {
    auto cfg = bundledMachine();
    cfg.parameters.set(576, 0); // fixed setter input not enabled
    ProgramRun r = runProgram(cfg, lines({"#1502 = 2", "M98 P502", "M30"}));
    expectMacroAlarm(r, 5, "固定对刀信号未设置! the fixed setter input, params 575-577, is not set");
}

} // namespace
