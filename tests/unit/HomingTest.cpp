// 回零 homing through the controller API: switches as inputs, speeds, directions, the position after
// homing and the homed flags; param 220 refusing unhomed automatic runs.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

controller::RunSettings unhomed() {
    controller::RunSettings s;
    s.homed = false;
    return s;
}

config::MachineConfig oneSwitchMachine() {
    auto cfg = m350Machine();
    cfg.parameters.set(551, 24); // Z switch on IN24, enabled, active low
    cfg.parameters.set(552, 1);
    cfg.parameters.set(553, 0);
    cfg.parameters.set(106, 1);  // one approach
    cfg.parameters.set(109, 600); // 10 mm/s
    cfg.parameters.set(114, 1);  // toward +Z
    cfg.parameters.set(118, 120); // 2 mm/s for the back-off
    cfg.parameters.set(124, -5); // Z after homing
    cfg.parameters.set(62, 1e9); // ramps negligible: times are distance / speed
    cfg.homeSwitchDistance = {0, 0, 30, 0, 0};
    return cfg;
}

TEST(Homing, AxisRunsToItsSwitchBacksOffAndTakesTheHomePosition) {
    controller::Controller c(oneSwitchMachine(), unhomed());
    EXPECT_TRUE(c.homing().needsBootHomingPrompt());
    EXPECT_DOUBLE_EQ(c.variable(1543).number, 1); // IN24 released
    EXPECT_FALSE(c.homing().home({2}).has_value());
    EXPECT_TRUE(c.homing().homed(2));
    EXPECT_DOUBLE_EQ(c.variable(1517).number, 1);
    EXPECT_DOUBLE_EQ(c.variable(882).number, -5);
    EXPECT_DOUBLE_EQ(c.variable(1543).number, 1); // released again after the back-off
    // 30 mm at 10 mm/s, then 2 mm back at 2 mm/s
    controller::RunReport r = c.status().report();
    EXPECT_NEAR(r.simTime, 3.0 + 1.0, 1e-6);
}

TEST(Homing, AxisWithoutASwitchCannotHome) {
    controller::Controller c(oneSwitchMachine(), unhomed());
    auto alarm = c.homing().home({0});
    ASSERT_TRUE(alarm.has_value());
    EXPECT_EQ(alarm->code, AlarmCode::NotHomed);
    EXPECT_NE(alarm->message.find("params 545-547"), std::string::npos) << alarm->message;
    EXPECT_FALSE(c.homing().homed(0));
}

TEST(Homing, BundledMachineHomesXYZAndRunsAProgram) {
    controller::Controller c(bundledMachine(), unhomed());
    ASSERT_FALSE(c.homing().home(c.homing().homeableAxes()).has_value());
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_TRUE(c.homing().homed(axis)) << axis;
    }
    EXPECT_FALSE(c.homing().needsBootHomingPrompt());
    std::string path = writeTempFile(lines({"G53 X10", "M30"}));
    ASSERT_TRUE(c.loadFile(path));
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
}

TEST(Homing, Param220RefusesAnUnhomedAutomaticRunButNotMdi) {
    auto cfg = oneSwitchMachine();
    cfg.parameters.set(220, 1);
    auto run = runProgram(cfg, lines({"#100 = 1", "M30"}), unhomed());
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::NotHomed);
    EXPECT_NE(run.report.alarm->message.find("机械未归零不能自动加工!"), std::string::npos);
    EXPECT_DOUBLE_EQ(run.number(100), 0); // nothing ran

    controller::Controller mdi(cfg, unhomed());
    ASSERT_TRUE(mdi.loadMdi({"#100 = 1"}));
    EXPECT_EQ(mdi.run().status, controller::RunStatus::Ok);
}

} // namespace
