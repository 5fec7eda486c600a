// The operator's manual motion: jog keys (CONT, STEP), the handwheel in MPG mode, soft limits,
// the spindle override and the IO page's output switches.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using controller::Controller;
using RunState = Controller::RunState;
using JogMode = controller::JogMode;

// Low jog speed 600 mm/min (10 mm/s) on X and Y, started at 100 mm/s^2 and stopped at 50 mm/s^2.
config::MachineConfig machine() {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 500);
    for (int axis = 0; axis < 2; ++axis) {
        cfg.parameters.set(param::kManualLowSpeedX + axis, 600);
        cfg.parameters.set(param::kManualStartAccelerationX + axis, 100);
        cfg.parameters.set(param::kManualStopAccelerationX + axis, 50);
    }
    return cfg;
}

std::unique_ptr<Controller> idle(config::MachineConfig cfg = machine()) {
    return std::make_unique<Controller>(std::move(cfg), controller::RunSettings{});
}

double x(Controller& c) { return c.displayPosition()(0); }

TEST(ManualJog, ContinuousMovesWhileHeldAndBrakesOnRelease) {
    auto c = idle();
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->advance(1.0);
    EXPECT_NEAR(x(*c), 9.5, 1e-9); // 0.1 s ramp (0.5 mm) + 0.9 s at 10 mm/s
    EXPECT_TRUE(c->panelStatus().jogging);
    c->advance(1.0);
    EXPECT_NEAR(x(*c), 19.5, 1e-9); // still going while the key is down
    c->manual().jogRelease(0);
    c->advance(0.1);
    EXPECT_NEAR(x(*c), 19.5 + 1.0 - 0.25, 1e-9); // braking at 50 mm/s^2 (param 55)
    EXPECT_TRUE(c->panelStatus().jogging);
    c->advance(1.0);
    EXPECT_NEAR(x(*c), 20.5, 1e-9); // 10^2 / (2 * 50) = 1 mm after the release
    EXPECT_FALSE(c->panelStatus().jogging);
    c->advance(5.0);
    EXPECT_NEAR(x(*c), 20.5, 1e-9);
}

TEST(ManualJog, HighSpeedAndOverrideSetTheSpeed) {
    auto cfg = machine();
    cfg.parameters.set(param::kManualHighSpeedX, 1200);
    cfg.parameters.set(param::kManualMaxSpeedX, 900); // caps the high speed
    auto c = idle(std::move(cfg));
    c->manual().setJogHighSpeed(true);
    EXPECT_DOUBLE_EQ(c->manual().setJogOverride(500.0), 150.0);
    EXPECT_DOUBLE_EQ(c->manual().setJogOverride(50.0), 50.0);
    ASSERT_TRUE(c->manual().jogPress(0, -1));
    c->advance(2.0);
    // 1200 mm/min at 50 % = 10 mm/s, under the 15 mm/s cap: 0.1 s ramp, then 1.9 s
    EXPECT_NEAR(x(*c), -(0.5 + 19.0), 1e-9);
    c->manual().jogRelease(0);
    c->manual().setJogOverride(100.0);
    c->advance(2.0);
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->advance(2.0);
    // 1200 mm/min capped at 900 (15 mm/s): ramp 0.15 s (1.125 mm), then 1.85 s
    EXPECT_NEAR(x(*c), -20.5 + 1.125 + 15.0 * 1.85, 1e-9);
}

TEST(ManualJog, StepMovesExactlyOneStep) {
    auto c = idle();
    c->manual().setJogMode(JogMode::Step);
    EXPECT_DOUBLE_EQ(c->manual().jogStep(), 0.1);
    c->manual().setJogStep(1.0);
    c->manual().setJogStep(-3.0); // ignored
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->manual().jogRelease(0);
    c->advance(10.0);
    EXPECT_NEAR(x(*c), 1.0, 1e-12);
    ASSERT_TRUE(c->manual().jogPress(1, -1));
    c->advance(10.0);
    EXPECT_NEAR(c->displayPosition()(1), -1.0, 1e-12);
    EXPECT_NEAR(x(*c), 1.0, 1e-12);
    controller::PanelStatus s = c->panelStatus();
    EXPECT_EQ(s.jogMode, JogMode::Step);
    EXPECT_DOUBLE_EQ(s.jogStep, 1.0);
    EXPECT_FALSE(s.jogging);
}

TEST(ManualJog, RefusedWhileAProgramRunsOrHolds) {
    auto c = idle();
    ASSERT_TRUE(c->loadMdi({"G01 X100 F600", "M30"}));
    ASSERT_TRUE(c->start());
    c->advance(1.0);
    EXPECT_FALSE(c->manual().jogPress(1, +1));
    c->manual().setJogMode(JogMode::Mpg);
    EXPECT_FALSE(c->manual().wheelTurn(1, 10, 5, 0.1));
    EXPECT_FALSE(c->manual().setOutputByOperator(3, 1));
    c->hold();
    EXPECT_EQ(c->runState(), RunState::Hold);
    c->manual().setJogMode(JogMode::Step);
    EXPECT_FALSE(c->manual().jogPress(1, +1));
    c->resume();
    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    EXPECT_NEAR(c->displayPosition()(1), 0.0, 1e-12); // Y never moved
    EXPECT_TRUE(c->manual().jogPress(1, +1));
}

TEST(ManualJog, RefusedInAlarmAndEStop) {
    auto c = idle();
    c->emergencyStop();
    EXPECT_FALSE(c->manual().jogPress(0, +1));
    EXPECT_FALSE(c->manual().setOutputByOperator(3, 1));
}

TEST(ManualJog, WheelMovesDetentsTimesMultiplierTimesParam172) {
    auto cfg = machine();
    cfg.parameters.set(param::kMpgDistance, 0.005);
    auto c = idle(std::move(cfg));
    EXPECT_FALSE(c->manual().wheelTurn(0, 10, 25, 1.0)); // not in MPG mode
    c->manual().setJogMode(JogMode::Mpg);
    EXPECT_FALSE(c->manual().jogPress(0, +1));          // the keys do nothing in MPG mode
    EXPECT_FALSE(c->manual().wheelTurn(0, 5, 25, 1.0)); // x1, x10, x100 only
    ASSERT_TRUE(c->manual().wheelTurn(0, 10, 25, 1.0));
    c->advance(10.0);
    EXPECT_NEAR(x(*c), 25 * 10 * 0.005, 1e-12);
    ASSERT_TRUE(c->manual().wheelTurn(2, 100, -2, 1.0));
    c->advance(10.0);
    EXPECT_NEAR(c->displayPosition()(2), -2 * 100 * 0.005, 1e-12);
}

TEST(ManualJog, Param175ReversesTheWheel) {
    auto cfg = machine();
    cfg.parameters.set(param::kMpgReversed, 1);
    auto c = idle(std::move(cfg));
    c->manual().setJogMode(JogMode::Mpg);
    ASSERT_TRUE(c->manual().wheelTurn(0, 10, 25, 1.0));
    c->advance(10.0);
    EXPECT_NEAR(x(*c), -25 * 10 * 0.004, 1e-12); // param 172 unset: the factory 0.004 mm
}

TEST(ManualJog, TheAxisFollowsTheWheelNoFasterThanItTurns) {
    auto c = idle();
    c->manual().setJogMode(JogMode::Mpg);
    ASSERT_TRUE(c->manual().wheelTurn(0, 1, 10, 1.0)); // 0.04 mm over one second
    c->advance(0.5);
    EXPECT_NEAR(x(*c), 0.02, 1e-4);
    EXPECT_TRUE(c->panelStatus().jogging);
    c->advance(1.0);
    EXPECT_NEAR(x(*c), 0.04, 1e-12);
}

// Param 171 手轮精准控制模式: 1 (关闭, the factory value) stops the axis when the wheel stops; 0
// (开启) runs out every pulse. 40 detents at x100 in one second ask 16 mm of an axis the wheel's
// x100 speed (178: 100 mm/min) lets run 1.67 mm in that second.
TEST(ManualJog, Param171OneStopsTheAxisWhenTheWheelStops) {
    auto cfg = machine();
    cfg.parameters.set(param::kMpgPrecise, 1);
    auto c = idle(std::move(cfg));
    c->manual().setJogMode(JogMode::Mpg);
    ASSERT_TRUE(c->manual().wheelTurn(0, 100, 40, 1.0));
    c->advance(1.0);
    const double stopped = x(*c);
    EXPECT_GT(stopped, 1.5);
    EXPECT_LE(stopped, 100.0 / 60.0 + 1e-9);
    EXPECT_FALSE(c->panelStatus().jogging) << "at rest as the wheel stops";
    c->advance(10.0);
    EXPECT_NEAR(x(*c), stopped, 1e-12) << "the pulses it could not run are dropped";
}

TEST(ManualJog, Param171ZeroRunsOutEveryPulse) {
    auto cfg = machine();
    cfg.parameters.set(param::kMpgPrecise, 0);
    auto c = idle(std::move(cfg));
    c->manual().setJogMode(JogMode::Mpg);
    ASSERT_TRUE(c->manual().wheelTurn(0, 100, 40, 1.0));
    c->advance(1.0);
    EXPECT_TRUE(c->panelStatus().jogging) << "still running out the pulses";
    c->advance(11.0);
    EXPECT_NEAR(x(*c), 40 * 100 * 0.004, 1e-9);
}

// A wheel turned in short bursts with 171 = 1: the axis never runs behind the wheel.
TEST(ManualJog, Param171OneNeverLagsTheWheel) {
    auto cfg = machine();
    cfg.parameters.set(param::kMpgPrecise, 1);
    auto c = idle(std::move(cfg));
    c->manual().setJogMode(JogMode::Mpg);
    for (int frame = 0; frame < 60; ++frame) {
        c->manual().wheelTurn(0, 100, 2, 1.0 / 60.0);
        c->advance(1.0 / 60.0);
    }
    const double atStop = x(*c);
    EXPECT_GT(atStop, 0.0);
    c->advance(5.0);
    EXPECT_NEAR(x(*c), atStop, 1e-9);
}

TEST(ManualJog, SoftLimitStopsAContinuousJog) {
    auto cfg = machine();
    cfg.parameters.set(param::kSoftLimitsEnabled, 1);
    cfg.parameters.set(param::kSoftLimitPositiveX, 20);
    cfg.parameters.set(param::kSoftLimitNegativeX, -5);
    auto c = idle(std::move(cfg));
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->advance(10.0);
    EXPECT_NEAR(x(*c), 20.0, 1e-9);
    EXPECT_FALSE(c->panelStatus().jogging);
    c->manual().jogRelease(0);
    EXPECT_FALSE(c->manual().jogPress(0, +1)); // at the limit: no further
    ASSERT_TRUE(c->manual().jogPress(0, -1));
    c->advance(10.0);
    EXPECT_NEAR(x(*c), -5.0, 1e-9);
}

TEST(ManualJog, ContinuousJogWithoutSoftLimitsRunsToTheLongTravelBound) {
    auto c = idle();
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->advance(1e6);
    EXPECT_NEAR(x(*c), controller::ManualControl::kJogTravel, 1e-6);
}

TEST(ManualJog, StartWaitsForTheJogToEnd) {
    auto c = idle();
    ASSERT_TRUE(c->loadMdi({"G01 Y10 F600"}));
    ASSERT_TRUE(c->manual().jogPress(0, +1));
    c->advance(0.5);
    EXPECT_FALSE(c->start());
    c->manual().jogRelease(0);
    c->advance(1.0);
    EXPECT_TRUE(c->start());
}

TEST(ManualJog, SpindleOverrideClampsAndTheShownSpeedFollows) {
    auto c = idle();
    EXPECT_DOUBLE_EQ(c->manual().setSpindleOverride(200.0), 150.0);
    EXPECT_DOUBLE_EQ(c->manual().setSpindleOverride(10.0), 50.0);
    EXPECT_DOUBLE_EQ(c->manual().setSpindleOverride(80.0), 80.0);
    ASSERT_TRUE(c->loadMdi({"M03 S10000"}));
    ASSERT_TRUE(c->start());
    c->advance(10.0);
    controller::PanelStatus s = c->panelStatus();
    EXPECT_DOUBLE_EQ(s.spindleOverride, 80.0);
    EXPECT_DOUBLE_EQ(s.spindleRpm, 8000.0);
}

TEST(ManualJog, OperatorSwitchesAnOutputButNotWhileRunning) {
    auto c = idle();
    EXPECT_TRUE(c->manual().setOutputByOperator(5, 1));
    EXPECT_EQ(c->panelStatus().outputs[4], 1);
    EXPECT_FALSE(c->manual().setOutputByOperator(22, 1));
    EXPECT_FALSE(c->manual().setOutputByOperator(5, 2));
    ASSERT_TRUE(c->loadMdi({"G01 X10 F600", "M30"}));
    ASSERT_TRUE(c->start());
    c->advance(0.5);
    EXPECT_FALSE(c->manual().setOutputByOperator(5, 0));
    EXPECT_EQ(c->panelStatus().outputs[4], 1);
    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    EXPECT_TRUE(c->manual().setOutputByOperator(5, 0));
    EXPECT_EQ(c->panelStatus().outputs[4], 0);
}

TEST(ManualJog, JogsOnTheBundledMachineWithItsMagazine) {
    auto c = idle(bundledMachine());
    const double start = x(*c);
    c->manual().setJogMode(JogMode::Step);
    c->manual().setJogStep(1.0);
    ASSERT_TRUE(c->manual().jogPress(0, -1));
    c->advance(5.0);
    EXPECT_NEAR(x(*c), start - 1.0, 1e-12);
    EXPECT_EQ(c->runState(), RunState::Idle);
}

} // namespace
