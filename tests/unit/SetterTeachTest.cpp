// XY位置教导 / Z位置教导: O506 and O507 (slib-probe.nc) store the machine position where the spindle
// stands as the fixed setter's X Y (params 135, 136) or as where probing starts (param 137). The
// setter itself stays where the simulated world has it, so teaching the wrong place shows.
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(SetterTeach, XYTeachStoresTheMachineXYOnly) {
    ProgramRun r = runProgram(bundledMachine(), lines({"G53 X512.25 Y48.5 Z-33.3", "M98 P506", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(635), 512.25, 1e-9);
    EXPECT_NEAR(r.number(636), 48.5, 1e-9);
    EXPECT_NEAR(r.number(637), -30, 1e-9); // param 137 as params.toml has it
    EXPECT_EQ(r.report.messages.back(), "固定对刀仪XY位置: X512.250 Y48.500");
}

TEST(SetterTeach, ZTeachStoresTheMachineZOnly) {
    ProgramRun r = runProgram(bundledMachine(), lines({"G53 X10 Y20 Z-53.677", "M98 P507", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(637), -53.677, 1e-9);
    EXPECT_NEAR(r.number(635), 555.269, 1e-9);
    EXPECT_EQ(r.report.messages.back(), "固定对刀仪Z位置: Z-53.677");
}

TEST(SetterTeach, TaughtOverTheSetterTheNextSettingStartsThere) {
    // taught 40 mm above T3's trip height: the setting probes down from there
    controller::RunSettings settings;
    settings.tool = 3;
    ProgramRun r = runProgram(bundledMachine(), lines({"G53 X555.269 Y66.381 Z-21.305", "M98 P506", "M98 P507",
                                                        "G53 Z0", "#1502 = 2", "M98 P502", "M30"}),
                              settings);
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(637), -21.305, 1e-9);
    EXPECT_NEAR(r.number(1432), -61.305, 1e-9);
}

TEST(SetterTeach, TaughtBesideTheSetterTheSettingNeverTrips) {
    // the setter is 10 mm in diameter: 8 mm off, the tool comes down beside it
    controller::RunSettings settings;
    settings.tool = 3;
    ProgramRun r = runProgram(bundledMachine(),
                              lines({"G53 X563.269 Y66.381", "M98 P506", "#1502 = 2", "M98 P502", "M30"}), settings);
    ASSERT_EQ(r.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SkipNotTriggered);
}

TEST(SetterTeach, UnhomedAxesCannotBeTaught) {
    controller::RunSettings settings;
    settings.homed = false;
    ProgramRun xy = runProgram(bundledMachine(), lines({"#1517 = 1", "M98 P506", "M30"}), settings);
    expectMacroAlarm(xy, 2, "X,Y轴机械未归零! home X and Y before teaching the setter's position");
    EXPECT_NEAR(xy.number(635), 555.269, 1e-9);
    ProgramRun z = runProgram(bundledMachine(), lines({"#1515 = 1", "#1516 = 1", "M98 P507", "M30"}), settings);
    expectMacroAlarm(z, 2, "Z轴机械未归零! home Z before teaching where probing starts");
    ProgramRun homedXY = runProgram(bundledMachine(), lines({"#1515 = 1", "#1516 = 1", "M98 P506", "M30"}), settings);
    EXPECT_RUN_OK(homedXY);
}

} // namespace
