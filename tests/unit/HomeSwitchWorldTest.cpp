// The home switches of the simulated world: a macro that homes by G31 against a home-switch input
// (as a factory O501 may) finds each switch where native homing does, before and after homing;
// the input reads the switch by where the axis stands.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using controller::Controller;

constexpr int kXSwitchPin = 22;

// X's home switch on IN22, active at 0 (NPN), homing toward -X; the world has it 100 mm away.
config::MachineConfig machineWithXSwitch() {
    config::MachineConfig cfg = test::m350Machine();
    cfg.parameters.set(param::kHomeSwitchX, kXSwitchPin);
    cfg.parameters.set(param::kHomeSwitchX + 1, 1);
    cfg.parameters.set(param::kHomeSwitchX + 2, 0);
    cfg.homeSwitchDistance[0] = 100.0;
    return cfg;
}

controller::RunSettings unhomed() {
    controller::RunSettings s;
    s.homed = false;
    return s;
}

// a user's O501 for X: fast onto the switch, off it, slowly onto it again
const std::vector<std::string> kMacroHoming{
    "G91 G31 X-500 F1000 P22 L0 K0 Q1", "#101 = #1925", // where it tripped
    "G91 G31 X10 F200 P22 L1 K0 Q1",    "#102 = #1925", // where it let go
    "G91 G31 X-10 F100 P22 L0 K0 Q1",   "#103 = #1925",
};

TEST(HomeSwitchWorld, AMacroFindsTheSwitchWhereTheWorldHasIt) {
    Controller c(machineWithXSwitch(), unhomed());
    ASSERT_TRUE(c.loadMdi(kMacroHoming));
    auto report = c.run();
    ASSERT_EQ(report.status, controller::RunStatus::Ok) << (report.alarm ? report.alarm->message : "");
    EXPECT_NEAR(c.variable(101).number, -100.0, 1e-6);
    EXPECT_NEAR(c.variable(102).number, -100.0, 1e-5);
    EXPECT_NEAR(c.variable(103).number, -100.0, 1e-5);
}

TEST(HomeSwitchWorld, TheSwitchStaysWherePhysicallyItIsAfterJogsAndHoming) {
    Controller c(machineWithXSwitch(), unhomed());
    ASSERT_TRUE(c.loadMdi({"G91 G1 X-30 F3000"})); // 30 mm closer before homing
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    const double before = c.status().report().simTime;
    ASSERT_FALSE(c.homing().home({0}));
    // param 122 = 0: the switch, 2 mm beyond where homing leaves X, is now at machine X -2
    EXPECT_NEAR(c.status().report().machine(0), 0.0, 1e-9);
    ASSERT_TRUE(c.loadMdi(kMacroHoming));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_NEAR(c.variable(101).number, -2.0, 1e-6);
    EXPECT_GT(c.status().report().simTime, before);
}

TEST(HomeSwitchWorld, TheInputReadsTheSwitchByWhereTheAxisStands) {
    Controller c(machineWithXSwitch(), unhomed());
    ASSERT_TRUE(c.loadMdi({"#101 = #[1519 + 22]", "G91 G0 X-100", "#102 = #[1519 + 22]", "G91 G0 X5",
                           "#103 = #[1519 + 22]"}));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_EQ(c.variable(101).number, 1); // released
    EXPECT_EQ(c.variable(102).number, 0); // on the switch
    EXPECT_EQ(c.variable(103).number, 1);
}

TEST(HomeSwitchWorld, ASwitchNeverReachedAlarmsInG31) {
    Controller c(machineWithXSwitch(), unhomed());
    ASSERT_TRUE(c.loadMdi({"G91 G31 X-50 F1000 P22 L0 K0 Q1"}));
    auto report = c.run();
    EXPECT_EQ(report.status, controller::RunStatus::Alarm);
    ASSERT_TRUE(report.alarm);
    EXPECT_NE(report.alarm->message.find("IN22"), std::string::npos) << report.alarm->message;
}

} // namespace
