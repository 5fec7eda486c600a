// 试切 handwheel-guided run: the program advances only while the wheel turns, at an override that
// follows the wheel's speed, ramps to rest when it stops, and retraces (or holds) when it turns
// backwards.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace m350;
using namespace m350::test;
using controller::Controller;
using RunState = Controller::RunState;
using GuideReverse = controller::GuideReverse;

constexpr double kFrame = 0.05; // the panel's display step

std::unique_ptr<Controller> guided(std::initializer_list<std::string> mdi) {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 500); // G01 acceleration: at 10 mm/s the ramps take 0.02 s
    auto c = std::make_unique<Controller>(std::move(cfg), controller::RunSettings{});
    EXPECT_TRUE(c->loadMdi(std::vector<std::string>(mdi)));
    c->manual().setHandwheelGuide(true);
    EXPECT_TRUE(c->start());
    return c;
}

// Turns the wheel for `seconds` at `detentsPerFrame` (x10 unless said), the display following.
// x10 moves 0.04 mm a detent and its speed is 50 mm/min: one detent a frame (0.8 mm/s) asks for
// 96 %, two for more than 100 %.
void turn(Controller& c, int detentsPerFrame, double seconds, int multiplier = 10) {
    for (double t = 0.0; t < seconds - 1e-9; t += kFrame) {
        bool guiding = c.manual().wheelTurn(0, multiplier, detentsPerFrame, kFrame);
        EXPECT_TRUE(guiding || c.runState() == RunState::Finished); // the end shown, the wheel has nothing to guide
        c.advance(kFrame);
    }
}

machine::Axes at(Controller& c) { return c.displayPosition(); }

TEST(HandwheelGuide, NeverAdvancesWithoutTheWheel) {
    auto c = guided({"G01 X100 F600", "M30"});
    EXPECT_EQ(c->advance(100.0), RunState::Running);
    EXPECT_EQ(at(*c)(0), 0.0);
    controller::PanelStatus s = c->panelStatus();
    EXPECT_TRUE(s.guide);
    EXPECT_EQ(s.guideDirection, 0);
    EXPECT_EQ(s.guideOverride, 0.0);
}

TEST(HandwheelGuide, AdvancesWhileTheWheelTurnsAndDeceleratesToRestAfter) {
    auto c = guided({"G01 X100 F600", "M30"});
    turn(*c, 1, 2.0);
    controller::PanelStatus s = c->panelStatus();
    EXPECT_EQ(s.guideDirection, 1);
    EXPECT_NEAR(s.guideOverride, 96.0, 1e-6);
    // 0.96 s of ramp (half the time's worth) and about 1 s at 96 %: some 14 mm at 10 mm/s
    const double moving = at(*c)(0);
    EXPECT_GT(moving, 12.0);
    EXPECT_LT(moving, 16.0);
    c->advance(kFrame);
    EXPECT_GT(at(*c)(0), moving); // still moving while the override decays (5 % per 10 ms)
    c->advance(0.5);
    const double rest = at(*c)(0);
    EXPECT_LT(rest - moving, 2.0);
    EXPECT_EQ(c->panelStatus().guideOverride, 0.0);
    EXPECT_EQ(c->panelStatus().guideDirection, 0);
    EXPECT_EQ(c->advance(30.0), RunState::Running);
    EXPECT_EQ(at(*c)(0), rest);
}

TEST(HandwheelGuide, AFasterWheelGivesAHigherOverride) {
    auto slow = guided({"G01 X100 F600", "M30"});
    auto fast = guided({"G01 X100 F600", "M30"});
    turn(*slow, 1, 1.5, 1); // x1: 0.08 mm/s against 20 mm/min: 24 %
    turn(*fast, 1, 1.5, 10);
    EXPECT_NEAR(slow->panelStatus().guideOverride, 24.0, 1e-6);
    EXPECT_NEAR(fast->panelStatus().guideOverride, 96.0, 1e-6);
    EXPECT_GT(at(*fast)(0), 2.0 * at(*slow)(0));
    turn(*fast, 3, 1.0, 10); // faster still: capped at 100 % (param 295 unset)
    EXPECT_NEAR(fast->panelStatus().guideOverride, 100.0, 1e-6);
}

TEST(HandwheelGuide, RetraceRunsBackAlongThePathAcrossACornerAndForwardFinishes) {
    auto c = guided({"G01 X20 F600", "G01 Y20", "M30"});
    turn(*c, 2, 3.5);
    const machine::Axes reached = at(*c);
    ASSERT_NEAR(reached(0), 20.0, 1e-9);
    ASSERT_GT(reached(1), 5.0); // well into the second move
    bool passedTheCorner = false;
    for (int frame = 0; frame < 80; ++frame) {
        ASSERT_TRUE(c->manual().wheelTurn(0, 10, -2, kFrame));
        c->advance(kFrame);
        const machine::Axes p = at(*c);
        // on the path: along X at Y 0, or along Y at X 20
        EXPECT_TRUE(std::abs(p(1)) < 1e-9 || std::abs(p(0) - 20.0) < 1e-9) << p.transpose();
        passedTheCorner = passedTheCorner || (p(0) < 15.0 && std::abs(p(1)) < 1e-9);
        if (frame == 20) {
            EXPECT_EQ(c->panelStatus().guideDirection, -1);
        }
    }
    EXPECT_TRUE(passedTheCorner);
    EXPECT_LT(at(*c)(0), reached(0));
    EXPECT_EQ(c->runState(), RunState::Running);
    turn(*c, 2, 12.0);
    EXPECT_EQ(c->runState(), RunState::Finished);
    EXPECT_NEAR(at(*c)(0), 20.0, 1e-9);
    EXPECT_NEAR(at(*c)(1), 20.0, 1e-9);
}

TEST(HandwheelGuide, RetraceGoesNoFurtherBackThanTheRunsStart) {
    auto c = guided({"G01 X20 F600", "M30"});
    turn(*c, 2, 2.0);
    turn(*c, -2, 6.0);
    EXPECT_NEAR(at(*c)(0), 0.0, 1e-12);
    EXPECT_GE(c->displayTime(), 0.0);
    turn(*c, 2, 1.5);
    EXPECT_GT(at(*c)(0), 0.0); // forward again at once
}

TEST(HandwheelGuide, ReverseWithHoldDoesNotMoveBack) {
    auto c = guided({"G01 X100 F600", "M30"});
    c->manual().setGuideReverse(GuideReverse::Hold);
    turn(*c, 1, 2.0);
    double previous = at(*c)(0);
    const double moving = previous;
    for (int frame = 0; frame < 40; ++frame) {
        ASSERT_TRUE(c->manual().wheelTurn(0, 10, -1, kFrame));
        c->advance(kFrame);
        EXPECT_GE(at(*c)(0), previous);
        previous = at(*c)(0);
    }
    EXPECT_LT(previous - moving, 2.0); // it came to rest
    EXPECT_EQ(c->panelStatus().guideOverride, 0.0);
    EXPECT_EQ(c->panelStatus().guideDirection, -1);
}

TEST(HandwheelGuide, TurningTheGuideOffResumesNormalSpeed) {
    auto c = guided({"G01 X20 F600", "G01 Y20", "M30"});
    turn(*c, 2, 3.5);
    turn(*c, -2, 2.0); // retraced part of the way
    c->manual().setHandwheelGuide(false);
    EXPECT_EQ(c->advance(0.5), RunState::Running);
    EXPECT_EQ(c->advance(10.0), RunState::Finished); // replayed at full speed, then the rest
    EXPECT_NEAR(at(*c)(0), 20.0, 1e-9);
    EXPECT_NEAR(at(*c)(1), 20.0, 1e-9);
    EXPECT_FALSE(c->panelStatus().guide);
}

TEST(HandwheelGuide, HoldDuringARetraceWaitsThereAndResumeGoesOn) {
    auto c = guided({"G01 X20 F600", "G01 Y20", "M30"});
    turn(*c, 2, 3.5);
    turn(*c, -2, 1.5);
    const machine::Axes retraced = at(*c);
    c->hold();
    EXPECT_EQ(c->runState(), RunState::Hold);
    c->advance(5.0);
    EXPECT_NEAR((at(*c) - retraced).norm(), 0.0, 1e-12);
    c->resume();
    turn(*c, 2, 12.0);
    EXPECT_EQ(c->runState(), RunState::Finished);
    EXPECT_NEAR(at(*c)(1), 20.0, 1e-9);
}

TEST(HandwheelGuide, ResetDuringARetraceLeavesTheMachineWhereItIsShown) {
    auto c = guided({"G01 X20 F600", "G01 Y20", "M30"});
    turn(*c, 2, 3.5);
    turn(*c, -2, 1.5);
    const machine::Axes retraced = at(*c);
    c->reset();
    EXPECT_NEAR((c->status().report().machine - retraced).norm(), 0.0, 1e-12);
    EXPECT_NEAR((at(*c) - retraced).norm(), 0.0, 1e-12);
}

TEST(HandwheelGuide, TheWheelDoesNotJogWhileItGuides) {
    auto c = guided({"G01 X10 F600", "M30"});
    c->manual().setJogMode(controller::JogMode::Mpg);
    turn(*c, 2, 1.0);
    EXPECT_NEAR(at(*c)(1), 0.0, 1e-12);
    EXPECT_GT(at(*c)(0), 0.0);
}

TEST(HandwheelGuide, RunWithoutAnOperatorIgnoresTheGuide) {
    auto cfg = m350Machine();
    auto c = std::make_unique<Controller>(std::move(cfg), controller::RunSettings{});
    ASSERT_TRUE(c->loadMdi({"G01 X10 F600", "M30"}));
    c->manual().setHandwheelGuide(true);
    controller::RunReport r = c->run();
    EXPECT_EQ(r.status, controller::RunStatus::Ok);
    EXPECT_NEAR(r.machine(0), 10.0, 1e-9);
}

} // namespace
