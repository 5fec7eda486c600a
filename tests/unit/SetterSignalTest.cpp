// G31 against the simulated fixed setter, with the faults the IO page can put on its input: the
// switch closes where the tip comes down to the setter's top and opens where it rises above it; a
// stuck input never changes; a delayed one is heard late, so the axes run on by feed x delay.
#include "core/machine/SimulatedMachine.h"

#include <gtest/gtest.h>

namespace {

using namespace m350::machine;

Axes at(double x, double y, double z) {
    Axes a = Axes::Zero();
    a << x, y, z, 0, 0;
    return a;
}

// A setter at X 100 Y 50 on IN12 (active 1), its top at -100; a 60 mm tool trips it at Z -40.
SimulatedMachine machineOverSetter() {
    SimulatedMachine m;
    MotionLimits l;
    l.rapidSpeed = 100.0;
    l.maxSpeed = 200.0;
    l.feedAcceleration = 500.0;
    l.rapidAcceleration = 1000.0;
    m.setLimits(l);
    ToolSetter setter;
    setter.port = 12;
    setter.activeLevel = 1;
    setter.x = 100;
    setter.y = 50;
    setter.top = -100;
    m.setToolSetter(setter);
    m.setToolLength(60);
    m.rapid(at(100, 50, -30));
    return m;
}

TEST(SetterSignal, TheSwitchClosesAtTheTripHeight) {
    SimulatedMachine m = machineOverSetter();
    ProbeResult down = m.probe(at(100, 50, -80), 300, 12, 1);
    EXPECT_TRUE(down.triggered);
    EXPECT_NEAR(down.position(2), -40, 1e-9);
    EXPECT_EQ(m.input(12), 1);
}

TEST(SetterSignal, LeavingItOpensTheSwitchWhereTheTipRisesAboveTheTop) {
    SimulatedMachine m = machineOverSetter();
    m.feed(at(100, 50, -40.5), 300); // pressed half a millimetre in
    ASSERT_EQ(m.input(12), 1);
    ProbeResult up = m.probe(at(100, 50, -30), 300, 12, 0);
    EXPECT_TRUE(up.triggered);
    EXPECT_NEAR(up.position(2), -40, 1e-9);
}

TEST(SetterSignal, BesideTheSetterNothingTrips) {
    SimulatedMachine m = machineOverSetter();
    m.rapid(at(110, 50, -30)); // 10 mm off a 5 mm radius
    ProbeResult down = m.probe(at(110, 50, -80), 300, 12, 1);
    EXPECT_FALSE(down.triggered);
    EXPECT_NEAR(m.position()(2), -80, 1e-9);
}

TEST(SetterSignal, AStuckInputNeverTrips) {
    SimulatedMachine m = machineOverSetter();
    m.forceInput(12, 0);
    ProbeResult down = m.probe(at(100, 50, -80), 300, 12, 1);
    EXPECT_FALSE(down.triggered);
    EXPECT_NEAR(m.position()(2), -80, 1e-9);
}

TEST(SetterSignal, ALateSignalLetsTheAxesRunOnByFeedTimesDelay) {
    SimulatedMachine m = machineOverSetter();
    m.setInputFault(12, InputFault::delayed(0.05));
    ProbeResult down = m.probe(at(100, 50, -80), 300, 12, 1); // 5 mm/s x 0.05 s = 0.25 mm
    EXPECT_TRUE(down.triggered);
    EXPECT_NEAR(down.position(2), -40.25, 1e-9);
    ProbeResult up = m.probe(at(100, 50, -30), 120, 12, 0); // 2 mm/s x 0.05 s = 0.1 mm
    EXPECT_TRUE(up.triggered);
    EXPECT_NEAR(up.position(2), -39.9, 1e-9);
}

TEST(SetterSignal, ASignalHeardOnlyAfterTheMoveEndedIsNone) {
    SimulatedMachine m = machineOverSetter();
    m.setInputFault(12, InputFault::delayed(1.0));
    ProbeResult down = m.probe(at(100, 50, -42), 300, 12, 1); // 2 mm past the trip, 5 mm late
    EXPECT_FALSE(down.triggered);
    EXPECT_NEAR(m.position()(2), -42, 1e-9);
}

} // namespace
