// Soft limits (param 155, limits 161-170) and homing: the limits guard an axis only while it is
// homed (#1515-#1519), as LinuxCNC's "the axis must be homed before MIN_LIMIT is in force". A
// factory O501 searches for the switch by a 10 m G31 and must run with the limits on; M98 P501
// X<axis> starts by forgetting that axis's position, so homing a homed machine again works too.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using controller::Controller;

constexpr int kXSwitchPin = 22;

// X homes toward - onto IN22 (active 0), 100 mm away at power-on; after homing X is 5. The soft
// limits are on: X from -2 to 500, the other axes +-1000.
config::MachineConfig machine() {
    config::MachineConfig cfg = m350Machine();
    cfg.parameters.set(param::kHomeSwitchX, kXSwitchPin);
    cfg.parameters.set(param::kHomeSwitchX + 1, 1);
    cfg.parameters.set(param::kHomeSwitchX + 2, 0);
    cfg.parameters.set(param::kHomePositionX, 5);
    cfg.homeSwitchDistance[0] = 100.0;
    cfg.parameters.set(param::kSoftLimitsEnabled, 1);
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        cfg.parameters.set(param::kSoftLimitNegativeX + axis, -1000);
        cfg.parameters.set(param::kSoftLimitPositiveX + axis, 1000);
    }
    cfg.parameters.set(param::kSoftLimitNegativeX, -2);
    cfg.parameters.set(param::kSoftLimitPositiveX, 500);
    return cfg;
}

// A library's O501 in the factory's manner: a long G31 onto the switch, off it, slowly back on,
// then the position after homing and the homed flag. It does not clear the flag itself.
config::MachineConfig withLibraryO501(config::MachineConfig cfg) {
    cfg.libraries.push_back({writeTempFile(lines({"O501(单轴回零 X)",
                                                  "G91 G31 X-10000 F3000 P22 L0 K0 Q1",
                                                  "G91 G01 X2 F3000",
                                                  "G91 G31 X-3 F100 P22 L0 K0 Q1",
                                                  "G90",
                                                  "#880 = #622",
                                                  "#1515 = 1",
                                                  "M99"})),
                             gcode::FileRole::GLibrary});
    return cfg;
}

controller::RunSettings unhomed() {
    controller::RunSettings s;
    s.homed = false;
    return s;
}

TEST(SoftLimitHoming, AHomedAxisIsStillHeldByItsLimits) {
    ProgramRun r = runProgram(machine(), lines({"G53 X100", "G53 X-10", "M30"}));
    ASSERT_EQ(r.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SoftLimit);
    EXPECT_EQ(r.report.alarm->line, 2u);
    EXPECT_NE(r.report.alarm->message.find("parameter 161"), std::string::npos) << r.alarmText();
}

TEST(SoftLimitHoming, AnAxisNotHomedHasNoTrustedPositionAndNoLimits) {
    ProgramRun r = runProgram(machine(), lines({"G53 X-50", "G91 G31 X-10000 F3000 P22 L0 K0 Q1", "#100 = #1925",
                                                "G90 G53 Y2000", "M30"}),
                              unhomed());
    EXPECT_RUN_OK(r);
    EXPECT_NEAR(r.number(100), -100.0, 1e-6); // the switch, beyond X's -2
    EXPECT_DOUBLE_EQ(r.report.machine(1), 2000.0);
}

TEST(SoftLimitHoming, TheLibrariesO501HomesWithTheLimitsOnFromPowerOn) {
    ProgramRun r = runProgram(withLibraryO501(machine()), lines({"M98 P501 X0", "#100 = #1515", "M30"}), unhomed());
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 1);
    EXPECT_DOUBLE_EQ(r.report.machine(0), 5.0);
}

TEST(SoftLimitHoming, HomingAHomedAxisAgainForgetsItsPositionFirst) {
    ProgramRun r = runProgram(withLibraryO501(machine()),
                              lines({"#100 = #1515", "M98 P501 X0", "#101 = #1515", "G53 X-1.5", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 1);
    EXPECT_EQ(r.number(101), 1);
    EXPECT_DOUBLE_EQ(r.report.machine(0), -1.5);

    // the flag is 0 while O501 runs
    auto cfg = machine();
    cfg.libraries.push_back({writeTempFile(lines({"O501", "#150 = #1515", "#1515 = 1", "M99"})),
                             gcode::FileRole::GLibrary});
    ProgramRun seen = runProgram(cfg, lines({"M98 P501 X0", "M30"}));
    EXPECT_RUN_OK(seen);
    EXPECT_EQ(seen.number(150), 0);
}

// Once the macro marks the axis homed, the limits hold it again.
TEST(SoftLimitHoming, AfterHomingTheLimitsHoldAgain) {
    ProgramRun r = runProgram(withLibraryO501(machine()), lines({"M98 P501 X0", "G53 X-10", "M30"}), unhomed());
    ASSERT_EQ(r.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.report.alarm->code, AlarmCode::SoftLimit);
    EXPECT_EQ(r.report.alarm->line, 2u);
}

TEST(SoftLimitHoming, TheFirmwaresOwnHomingAlsoClearsTheFlagUntilTheSwitch) {
    Controller c(machine(), controller::RunSettings{});
    ASSERT_TRUE(c.homing().homed(0));
    ASSERT_TRUE(c.setParameter(param::kHomeSwitchX + 1, 0)); // switch disabled: no search starts
    EXPECT_TRUE(c.homing().homeAxis(0, 0.0).has_value());
    EXPECT_TRUE(c.homing().homed(0)); // nothing moved: the position is still trusted
    ASSERT_TRUE(c.setParameter(param::kHomeSwitchX + 1, 1));
    ASSERT_TRUE(c.setParameter(param::kHomingSpeedX, 6000));
    EXPECT_FALSE(c.homing().homeAxis(0, 0.0).has_value());
    EXPECT_TRUE(c.homing().homed(0));
    EXPECT_DOUBLE_EQ(c.status().report().machine(0), 5.0);
}

TEST(SoftLimitHoming, AJogOfAnAxisNotHomedIsNotStoppedAtItsLimit) {
    auto cfg = machine();
    cfg.parameters.set(param::kManualLowSpeedX, 600);
    cfg.parameters.set(param::kManualStartAccelerationX, 100);
    cfg.parameters.set(param::kManualStopAccelerationX, 50);
    Controller homed(cfg, controller::RunSettings{});
    ASSERT_TRUE(homed.manual().jogPress(0, -1));
    homed.advance(10.0);
    EXPECT_NEAR(homed.displayPosition()(0), -2.0, 1e-9);

    Controller notHomed(cfg, unhomed());
    ASSERT_TRUE(notHomed.manual().jogPress(0, -1));
    notHomed.advance(10.0);
    EXPECT_LT(notHomed.displayPosition()(0), -50.0);
}

} // namespace
