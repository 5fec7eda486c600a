// The operator's controls in virtual time: a hold decelerates and the program resumes where it
// left; reset and E-stop stop at once with the outputs in their safe state.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

config::MachineConfig rampedMachine() {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 500); // G01 acceleration: at 10 mm/s the ramps take 0.02 s and 0.1 mm
    return cfg;
}

std::unique_ptr<controller::Controller> loaded(config::MachineConfig cfg, const std::string& program) {
    auto c = std::make_unique<controller::Controller>(std::move(cfg), controller::RunSettings{});
    EXPECT_TRUE(c->loadFile(writeTempFile(program)));
    EXPECT_TRUE(c->start());
    return c;
}

TEST(RunControl, HoldDeceleratesAndResumeFinishesTheMove) {
    auto c = loaded(rampedMachine(), lines({"G01 X100 F600", "M30"}));
    EXPECT_EQ(c->advance(5.0), RunState::Running);
    EXPECT_NEAR(c->displayPosition()(0), 49.9, 1e-9); // 0.1 mm ramp + 4.98 s at 10 mm/s
    c->hold();
    EXPECT_EQ(c->runState(), RunState::Hold);
    EXPECT_NEAR(c->displayPosition()(0), 50.0, 1e-9); // it stopped 0.1 mm further on
    EXPECT_EQ(c->advance(2.0), RunState::Hold);
    EXPECT_NEAR(c->displayPosition()(0), 50.0, 1e-9); // nothing moves while held
    c->resume();
    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    controller::RunReport r = c->status().report();
    EXPECT_EQ(r.status, controller::RunStatus::Ok);
    EXPECT_NEAR(r.machine(0), 100.0, 1e-9);
    // resumed at 7.0 s; the remaining 50 mm take 5.02 s; then M30's 0.1 ms (the G01 block's own
    // 0.1 ms lay behind the move the hold cut short)
    EXPECT_NEAR(r.simTime, 7.0 + 5.02 + 1e-4, 1e-9);
}

TEST(RunControl, HoldLiftsZByParam70WhenParam91SaysSo) {
    auto cfg = rampedMachine();
    cfg.parameters.set(91, 1);
    cfg.parameters.set(70, 3);
    auto c = loaded(std::move(cfg), lines({"G01 X100 F600", "M30"}));
    c->advance(1.0);
    c->hold();
    c->advance(2.0);
    EXPECT_NEAR(c->status().report().machine(2), 3.0, 1e-9);
    c->resume();
    c->advance(100.0);
    EXPECT_NEAR(c->status().report().machine(2), 0.0, 1e-9); // back down before the move went on
    EXPECT_NEAR(c->status().report().machine(0), 100.0, 1e-9);
}

TEST(RunControl, ResetStopsAtOnceSwitchesOutputsOffAndRewinds) {
    auto c = loaded(rampedMachine(), lines({"#1552 = 1", "M03 S1000", "G01 X100 F600", "M30"}));
    c->advance(3.0);
    EXPECT_EQ(c->status().report().outputs[0], 1);
    c->reset();
    EXPECT_EQ(c->runState(), RunState::Idle);
    controller::RunReport r = c->status().report();
    EXPECT_EQ(r.outputs[0], 0);
    EXPECT_GT(r.machine(0), 0.0);
    EXPECT_LT(r.machine(0), 100.0); // stopped mid-move
    EXPECT_TRUE(c->start());        // cycle start runs it again from the top
    EXPECT_EQ(c->advance(1000.0), RunState::Finished);
    EXPECT_NEAR(c->status().report().machine(0), 100.0, 1e-9);
}

TEST(RunControl, EmergencyStopIsAnAlarmWithEverythingOff) {
    auto c = loaded(rampedMachine(), lines({"#1552 = 1", "M03 S1000", "G01 X100 F600", "M30"}));
    c->advance(3.0);
    c->emergencyStop();
    EXPECT_EQ(c->runState(), RunState::EStop);
    controller::RunReport r = c->status().report();
    EXPECT_EQ(r.status, controller::RunStatus::Alarm);
    ASSERT_TRUE(r.alarm.has_value());
    EXPECT_EQ(r.alarm->code, AlarmCode::EmergencyStop);
    EXPECT_EQ(r.outputs[0], 0);
    EXPECT_EQ(c->advance(10.0), RunState::EStop); // nothing runs until reset
    c->reset();
    EXPECT_EQ(c->runState(), RunState::Idle);
}

} // namespace

namespace {

TEST(RunControl, FeedOverrideScalesFeedsUpToParam295AndRapidsWhenParam253Says) {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 1e9); // no measurable ramps
    cfg.parameters.set(282, 1e9);
    cfg.parameters.set(63, 6000);
    cfg.parameters.set(64, 100000);
    cfg.parameters.set(295, 120);
    auto timeOf = [&](const std::string& move, double percent, bool rapids) {
        auto c = cfg;
        c.parameters.set(253, rapids ? 1 : 0);
        controller::Controller controller(std::move(c), controller::RunSettings{});
        EXPECT_TRUE(controller.loadMdi({move}));
        double applied = controller.setFeedOverride(percent);
        controller::RunReport r = controller.run();
        return std::make_pair(applied, r.simTime);
    };
    EXPECT_NEAR(timeOf("G01 X100 F600", 100, false).second, 10.0, 1e-3);
    EXPECT_NEAR(timeOf("G01 X100 F600", 50, false).second, 20.0, 1e-3);
    auto capped = timeOf("G01 X100 F600", 200, false);
    EXPECT_EQ(capped.first, 120); // param 295
    EXPECT_NEAR(capped.second, 10.0 / 1.2, 1e-3);
    EXPECT_NEAR(timeOf("G00 X100", 50, false).second, 1.0, 1e-3); // G00 at param 63: 100 mm/s
    EXPECT_NEAR(timeOf("G00 X100", 50, true).second, 2.0, 1e-3);
}

} // namespace
