// 浮动对刀 on the default machine: a block of param 129's thickness lies on the work ([floating_setter]
// top); O502 with #1502 = 0 probes it from where the tool stands and sets the active work system's
// Z so that work Z 0 lies the thickness below the trip height.
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

double length(const config::MachineConfig& cfg, int tool) {
    return cfg.toolLengths[static_cast<std::size_t>(tool - 1)];
}

TEST(FloatingSetter, TheDefaultMachineHasOneOnIN13) {
    auto cfg = bundledMachine();
    ASSERT_TRUE(cfg.floatingSetterTop);
    EXPECT_EQ(*cfg.floatingSetterTop, -122.5);
    EXPECT_EQ(cfg.parameters.get(578), 13);
    EXPECT_EQ(cfg.parameters.get(128), 1);
}

TEST(FloatingSetter, ItsInputClosesWhereTheTipMeetsTheBlockWhereverXYAre) {
    auto cfg = bundledMachine();
    const double trip = *cfg.floatingSetterTop + length(cfg, 1);
    ProgramRun r = runProgram(cfg, lines({"G53 X50 Y300 Z-20", "#100 = #1532", "G53 Z" + std::to_string(trip),
                                          "#101 = #1532", "G53 X700 Y200", "#102 = #1532", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 0); // above the block
    EXPECT_EQ(r.number(101), 1); // on it
    EXPECT_EQ(r.number(102), 1); // still on it elsewhere: it lies on the work
}

TEST(FloatingSetter, SettingPutsWorkZeroTheThicknessBelowTheBlocksTop) {
    auto cfg = bundledMachine();
    cfg.offsets[1][2] = 0; // G54 Z not set yet
    const double top = *cfg.floatingSetterTop;
    const double trip = top + length(cfg, 1); // -56.177
    ProgramRun r = runProgram(cfg, lines({"G53 X300 Y200 Z-40", "#1502 = 0", "M98 P502", "G00 Z0", "M30"}));
    EXPECT_RUN_OK(r);
    // G54 Z = trip - thickness - T1's Z offset (param 930 = -53.677)
    EXPECT_NEAR(r.number(807), trip - 10 - (-53.677), 1e-9);
    EXPECT_NEAR(r.number(807), -12.5, 1e-9);
    // G0 Z0: the tip stands on the block's top minus its thickness, i.e. on the work
    EXPECT_NEAR(r.report.machine(2) - length(cfg, 1), top - 10, 1e-9);
    EXPECT_NEAR(r.report.machine(0), 300, 1e-9); // probed where it stood
    EXPECT_EQ(r.report.messages.back(), "对刀完成!");
}

TEST(FloatingSetter, TheActiveSystemAThinnerBlockAndAnotherToolAgree) {
    // G55 active, a 5 mm block, T3 whose stored Z offset is off by 7 mm: the work Z still comes
    // out so that Z0 puts the tip on the work
    auto cfg = bundledMachine();
    cfg.parameters.set(129, 5);
    cfg.parameters.set(932, -61.305 + 7);
    cfg.offsets[2][2] = 40;
    controller::RunSettings settings;
    settings.tool = 3;
    const double top = *cfg.floatingSetterTop;
    ProgramRun r = runProgram(cfg, lines({"G55", "G53 X100 Y100 Z-30", "#1502 = 0", "M98 P502", "G00 Z0", "M30"}),
                              settings);
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(812), top + length(cfg, 3) - 5 - (-61.305 + 7), 1e-9); // G55 Z
    EXPECT_NEAR(r.number(807), -12.5, 1e-9);                                    // G54 untouched
    EXPECT_NEAR(r.report.machine(2) - length(cfg, 3), top - 5, 1e-9);
}

TEST(FloatingSetter, SwitchedOffByParam128IsAnAlarm) {
    auto cfg = bundledMachine();
    cfg.parameters.set(128, 0);
    ProgramRun r = runProgram(cfg, lines({"G53 Z-40", "#1502 = 0", "M98 P502", "M30"}));
    expectMacroAlarm(r, 4, "浮动对刀仪无效! the floating setter is switched off: param 128");
    EXPECT_NEAR(r.number(807), -12.5, 1e-9);
}

TEST(FloatingSetter, WithoutTheInputIsAnAlarm) {
    auto cfg = bundledMachine();
    cfg.parameters.set(579, 0);
    ProgramRun r = runProgram(cfg, lines({"G53 Z-40", "#1502 = 0", "M98 P502", "M30"}));
    expectMacroAlarm(r, 5, "浮动对刀信号未设置! the floating setter input, params 578-580, is not set");
}

TEST(FloatingSetter, AMachineWithoutTheBlockNeverTrips) {
    auto cfg = bundledMachine();
    cfg.floatingSetterTop.reset();
    ProgramRun r = runProgram(cfg, lines({"G53 Z-40", "#1502 = 0", "M98 P502", "M30"}));
    EXPECT_EQ(r.report.status, controller::RunStatus::Alarm);
    ASSERT_TRUE(r.report.alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SkipNotTriggered);
}

} // namespace
