#include "core/machine/SimulatedMachine.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace m350::machine;

MotionLimits limits() {
    MotionLimits l;
    l.rapidSpeed = 100.0;   // mm/s
    l.maxSpeed = 200.0;
    l.feedAcceleration = 500.0;
    l.rapidAcceleration = 1000.0;
    l.spindleStartDelay = 1.5;
    l.spindleStopDelay = 0.5;
    return l;
}

Axes at(double x, double y = 0, double z = 0) {
    Axes a = Axes::Zero();
    a << x, y, z, 0, 0;
    return a;
}

TEST(SimulatedMachine, FeedMoveTakesItsTrapezoidTime) {
    SimulatedMachine m;
    m.setLimits(limits());
    m.feed(at(100), 3000); // 50 mm/s at 500 mm/s^2: 0.1 s ramps, 95 mm cruise: 2.1 s
    EXPECT_NEAR(m.time(), 2.1, 1e-12);
    EXPECT_DOUBLE_EQ(m.position()(0), 100.0);
    EXPECT_NEAR(m.positionAt(1.05)(0), 50.0, 1e-9); // halfway in time is halfway in space
    EXPECT_NEAR(m.positionAt(0.1)(0), 2.5, 1e-9);
}

TEST(SimulatedMachine, RapidUsesG00SpeedAndAcceleration) {
    SimulatedMachine m;
    m.setLimits(limits());
    m.rapid(at(0, 300)); // 100 mm/s at 1000 mm/s^2: 0.1 s ramps (10 mm), 290 mm cruise
    EXPECT_NEAR(m.time(), 3.1, 1e-12);
}

TEST(SimulatedMachine, FeedIsCappedByMaxSpeedAndScaledByOverride) {
    SimulatedMachine m;
    m.setLimits(limits());
    m.feed(at(400), 60000); // asks 1000 mm/s, capped at 200: 0.4 s ramps (80 mm), 320 mm cruise
    EXPECT_NEAR(m.time(), 2.4, 1e-12);
    SimulatedMachine half;
    half.setLimits(limits());
    half.setFeedOverride(0.5, false);
    half.feed(at(100), 3000); // 25 mm/s: 0.05 s ramps (1.25 mm), 98.75 mm cruise
    EXPECT_NEAR(half.time(), 0.1 + 98.75 / 25.0, 1e-12);
    half.rapid(at(100, 300)); // rapid not slowed unless param 253 says so
    EXPECT_NEAR(half.time(), 0.1 + 98.75 / 25.0 + 3.1, 1e-12);
}

TEST(SimulatedMachine, SpindleStartWaitsAndStopCoastsWithTheSensorFollowing) {
    SimulatedMachine m;
    m.setLimits(limits());
    m.setSpindleStoppedSensor({7, 0}); // IN07 reads 0 while stopped
    EXPECT_EQ(m.input(7), 0);
    m.spindle(SpindleState::Forward, 12000);
    EXPECT_NEAR(m.time(), 1.5, 1e-12); // waited for speed
    EXPECT_EQ(m.input(7), 1);
    m.spindle(SpindleState::Stop, 0);
    EXPECT_NEAR(m.time(), 1.5, 1e-12); // the program goes on while it coasts
    EXPECT_EQ(m.input(7), 1);
    m.dwell(0.4);
    EXPECT_EQ(m.input(7), 1);
    m.dwell(0.1);
    EXPECT_EQ(m.input(7), 0);
}

TEST(SimulatedMachine, IoLinkAnswersAfterItsDelayAndForcedInputsWin) {
    SimulatedMachine m;
    m.addLink({1, 11, 0.15, false});
    m.setOutput(1, 1);
    EXPECT_EQ(m.input(11), 0);
    m.dwell(0.15);
    EXPECT_EQ(m.input(11), 1);
    m.forceInput(11, 0);
    EXPECT_EQ(m.input(11), 0);
}

TEST(SimulatedMachine, MoveEventsCarryStartAndEndTimes) {
    struct Recorder : MachineObserver {
        std::vector<MachineEvent> events;
        void onMachineEvent(const MachineEvent& e) override { events.push_back(e); }
    } recorder;
    SimulatedMachine m(&recorder);
    m.setLimits(limits());
    m.feed(at(100), 3000);
    m.dwell(1.0);
    ASSERT_EQ(recorder.events.size(), 2u);
    EXPECT_EQ(recorder.events[0].type, MachineEvent::Type::Feed);
    EXPECT_DOUBLE_EQ(recorder.events[0].start, 0.0);
    EXPECT_NEAR(recorder.events[0].end, 2.1, 1e-12);
    EXPECT_NEAR(recorder.events[1].start, 2.1, 1e-12);
    EXPECT_NEAR(recorder.events[1].end, 3.1, 1e-12);
}

} // namespace

namespace {

// The level input IN11 reads at virtual time t (the machine's clock moved there by dwells).
int readAt(SimulatedMachine& m, double t) {
    m.dwell(t - m.time());
    return m.input(11);
}

TEST(SimulatedMachine, ADelayedInputShowsEveryChangeLate) {
    SimulatedMachine m;
    m.addLink({1, 11, 0.15, false});
    m.setInputFault(11, InputFault::delayed(2.0));
    m.setOutput(1, 1);
    EXPECT_EQ(readAt(m, 0.2), 0);  // the cylinder is out, the sensor does not say so yet
    EXPECT_EQ(readAt(m, 2.14), 0);
    EXPECT_EQ(readAt(m, 2.16), 1); // 0.15 s + 2 s late
    m.setInputFault(11, std::nullopt);
    EXPECT_EQ(m.input(11), 1);
}

TEST(SimulatedMachine, ABouncingInputChattersAfterEachChangeThenSettles) {
    SimulatedMachine m;
    m.addLink({1, 11, 0.15, false});
    m.setInputFault(11, InputFault::bouncing(0.05, 0.002));
    m.setOutput(1, 1);
    EXPECT_EQ(readAt(m, 0.1), 0);    // before the change: steady
    EXPECT_EQ(readAt(m, 0.1505), 1); // first bounce period: the new level
    EXPECT_EQ(readAt(m, 0.1525), 0); // second: back to the old one
    EXPECT_EQ(readAt(m, 0.1545), 1);
    EXPECT_EQ(readAt(m, 0.21), 1);   // settled after 50 ms
    m.setOutput(1, 0);               // and again on the way back
    EXPECT_EQ(readAt(m, 0.3605 + 0.0), 0);
    EXPECT_EQ(readAt(m, 0.3625), 1);
    EXPECT_EQ(readAt(m, 0.5), 0);
}

TEST(SimulatedMachine, AStuckInputIgnoresWhatDrivesIt) {
    SimulatedMachine m;
    m.addLink({1, 11, 0.15, false});
    m.setInputFault(11, InputFault::stuck(1));
    EXPECT_EQ(m.input(11), 1);
    m.setOutput(1, 1);
    m.setOutput(1, 0);
    EXPECT_EQ(readAt(m, 1.0), 1);
}

} // namespace
