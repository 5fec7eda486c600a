// Issue 13: --max-sim-time counts from the start of each run (and of each homing), not from the
// machine's power-on: a controller that has simulated more than the limit over many runs still runs
// a short program, a runaway still stops one limit after its own start, and a long hold is no
// runaway.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace {

using namespace m350;
using controller::Controller;
using controller::RunStatus;

controller::RunSettings limitOf(double seconds) {
    controller::RunSettings settings;
    settings.maxSimTime = seconds;
    return settings;
}

TEST(TimeLimitPerRun, AControllerPastTheLimitStillRunsAShortProgram) {
    Controller c(test::m350Machine(), limitOf(2.0));
    for (int run = 0; run < 3; ++run) {
        ASSERT_TRUE(c.loadMdi({"G04 P1500"}));
        ASSERT_EQ(c.run().status, RunStatus::Ok) << "run " << run;
    }
    ASSERT_GT(c.status().report().simTime, 4.0); // over twice the limit on the machine's clock
    ASSERT_TRUE(c.loadMdi({"G91 G01 X10 F6000"}));
    const controller::RunReport r = c.run();
    EXPECT_EQ(r.status, RunStatus::Ok) << (r.alarm ? r.alarm->message : std::string());
    EXPECT_NEAR(r.machine(0), 10.0, 1e-9);
}

TEST(TimeLimitPerRun, ARunawayStopsOneLimitAfterItsOwnStartAndSaysWhen) {
    Controller c(test::m350Machine(), limitOf(2.0));
    ASSERT_TRUE(c.loadMdi({"G04 P1500"}));
    ASSERT_EQ(c.run().status, RunStatus::Ok);
    ASSERT_TRUE(c.loadMdi({"G04 P1500"}));
    const double startedAt = c.run().simTime;
    ASSERT_TRUE(c.loadMdi({"G04 P99999999"}));
    const controller::RunReport r = c.run();
    ASSERT_EQ(r.status, RunStatus::Alarm);
    ASSERT_TRUE(r.alarm);
    EXPECT_EQ(r.alarm->code, AlarmCode::SimulatedTimeLimit);
    EXPECT_NEAR(r.simTime, startedAt + 2.0, 1e-3) << "the dwell is cut where the limit found it";
    EXPECT_NE(r.alarm->message.find("ran 2 s of simulated time"), std::string::npos) << r.alarm->message;
    std::ostringstream clock; // as the alarm prints it
    clock << "from " << startedAt << " s to " << r.simTime << " s of the machine's clock";
    EXPECT_NE(r.alarm->message.find(clock.str()), std::string::npos) << r.alarm->message;
}

TEST(TimeLimitPerRun, ALongHoldIsNoRunaway) {
    Controller c(test::m350Machine(), limitOf(2.0));
    ASSERT_TRUE(c.loadMdi({"G91 G01 X10 F600"})); // 1 s of feed
    ASSERT_TRUE(c.start());
    ASSERT_EQ(c.advance(0.5), Controller::RunState::Running);
    c.hold();
    ASSERT_EQ(c.advance(10.0), Controller::RunState::Hold); // the operator leaves it paused for 10 s
    c.resume();
    EXPECT_EQ(c.advance(5.0), Controller::RunState::Finished)
        << (c.status().report().alarm ? c.status().report().alarm->message : std::string());
    EXPECT_NEAR(c.status().report().machine(0), 10.0, 1e-9);
}

TEST(TimeLimitPerRun, HomingCountsFromItsOwnStart) {
    controller::RunSettings settings = limitOf(60.0);
    settings.homed = false;
    Controller c(test::bundledMachine(), settings);
    for (int run = 0; run < 2; ++run) {
        ASSERT_TRUE(c.loadMdi({"G04 P40000"}));
        ASSERT_EQ(c.run().status, RunStatus::Ok) << "run " << run;
    }
    ASSERT_GT(c.status().report().simTime, 60.0);
    const auto alarm = c.homing().home(c.homing().homeableAxes());
    EXPECT_FALSE(alarm) << alarm->message;
    EXPECT_TRUE(c.homing().homed(0) && c.homing().homed(1) && c.homing().homed(2));
}

} // namespace
