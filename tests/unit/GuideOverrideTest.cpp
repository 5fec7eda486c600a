// The handwheel guide's override model: ramps toward the wheel's target by param 180 per 10 ms
// step, decays by param 179 per step once the wheel stops, and passes through rest to reverse.
#include "core/controller/GuideOverride.h"

#include <gtest/gtest.h>

namespace {

using m350::controller::GuideOverride;

constexpr GuideOverride::Steps kSteps{0.01, 0.05};

TEST(GuideOverride, RampsTowardTheTargetByTheChangeStep) {
    GuideOverride g;
    g.turn(1, 0.8, 10.0);
    double progress = g.advance(0.5, kSteps);
    EXPECT_NEAR(g.value(), 0.5, 1e-9); // 50 steps of 1 %
    // the program time is the sum of the override over the steps: 0.01 s * (0 + 0.01 + ... + 0.49)
    EXPECT_NEAR(progress, 0.01 * 0.01 * 49 * 50 / 2, 1e-9);
    g.advance(1.0, kSteps);
    EXPECT_NEAR(g.value(), 0.8, 1e-9); // holds at the target
    EXPECT_EQ(g.direction(), 1);
}

TEST(GuideOverride, DecaysByTheStopStepOnceTheWheelStops) {
    GuideOverride g;
    g.turn(1, 0.5, 0.6);
    g.advance(0.6, kSteps);
    EXPECT_NEAR(g.value(), 0.5, 1e-9);
    g.advance(0.05, kSteps);
    EXPECT_NEAR(g.value(), 0.25, 1e-9); // five steps of 5 %
    g.advance(0.05, kSteps);
    EXPECT_EQ(g.value(), 0.0);
    EXPECT_EQ(g.direction(), 0);
    EXPECT_EQ(g.advance(10.0, kSteps), 0.0); // at rest nothing passes
}

TEST(GuideOverride, ReversingStopsFirstThenRunsBackwards) {
    GuideOverride g;
    g.turn(1, 0.5, 1.0);
    g.advance(1.0, kSteps);
    g.turn(-1, -0.5, 10.0);
    EXPECT_EQ(g.direction(), -1);
    g.advance(0.1, kSteps);
    EXPECT_NEAR(g.value(), 0.0, 1e-9); // ten stop steps of 5 %
    g.advance(0.2, kSteps);
    EXPECT_NEAR(g.value(), -0.2, 1e-9);
    EXPECT_LT(g.advance(0.1, kSteps), 0.0);
}

TEST(GuideOverride, AReverseTurnThatAsksForRestStopsAtTheStopStep) {
    GuideOverride g;
    g.turn(1, 0.5, 1.0);
    g.advance(1.0, kSteps);
    g.turn(-1, 0.0, 10.0); // Hold
    g.advance(0.05, kSteps);
    EXPECT_NEAR(g.value(), 0.25, 1e-9);
    g.advance(1.0, kSteps);
    EXPECT_EQ(g.value(), 0.0);
    EXPECT_EQ(g.direction(), -1); // the wheel still turns backwards: 逆切 shows
}

} // namespace
