// HoldMotion on its own: what a hold does to the machine as params 84, 91 and 70 say, what START
// undoes (in the order Z back down, spindle again, the rest of the move), what it reports of the
// rest for tool life, and that RESET forgets it all.
#include "core/controller/HoldMotion.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using controller::HoldMotion;
using machine::SimulatedMachine;

// A feed along X at 600 mm/min cut short 1 s in, with the spindle turning at 8000 rpm.
SimulatedMachine::Remainder cutShort(SimulatedMachine& machine) {
    machine.spindle(machine::SpindleState::Forward, 8000.0);
    machine::Axes to = machine::Axes::Zero();
    to(0) = 100.0;
    const double start = machine.time();
    machine.feed(to, 600.0);
    return machine.interrupt(start + 1.0, true);
}

// Param 84: the spindle stops on a hold; 91 and 70: Z rises 15 mm.
params::ParameterTable stopAndLift15() {
    params::ParameterTable p;
    p.set(param::kStopSpindleOnPause, 1);
    p.set(param::kPauseZMode, 1);
    p.set(param::kPauseLift, 15.0);
    return p;
}

TEST(HoldMotion, AHoldStopsTheSpindleAndLiftsZAsTheParametersSayAndStartUndoesIt) {
    const params::ParameterTable p = stopAndLift15();
    SimulatedMachine machine;
    HoldMotion hold(machine, p);
    const SimulatedMachine::Remainder rest = cutShort(machine);
    ASSERT_EQ(rest.kind, SimulatedMachine::Remainder::Kind::Feed);
    const machine::Axes stoppedAt = machine.position();

    hold.held(rest);
    EXPECT_EQ(machine.spindleState(), machine::SpindleState::Stop);
    EXPECT_DOUBLE_EQ(machine.position()(2), stoppedAt(2) + 15.0);

    const HoldMotion::Finished finished = hold.resume();
    EXPECT_TRUE(finished.cut) << "the rest of a feed cuts: tool life counts it";
    EXPECT_LT(finished.from, machine.time());
    EXPECT_EQ(machine.spindleState(), machine::SpindleState::Forward);
    EXPECT_DOUBLE_EQ(machine.spindleRpm(), 8000.0);
    EXPECT_DOUBLE_EQ(machine.position()(0), 100.0) << "the move cut short ends where it was going";
    EXPECT_DOUBLE_EQ(machine.position()(2), stoppedAt(2));

    EXPECT_FALSE(hold.resume().cut) << "START again has nothing left to finish";
}

TEST(HoldMotion, WithoutTheParametersTheSpindleTurnsOnAndZStays) {
    params::ParameterTable p;
    SimulatedMachine machine;
    HoldMotion hold(machine, p);
    const SimulatedMachine::Remainder rest = cutShort(machine);
    const machine::Axes stoppedAt = machine.position();
    hold.held(rest);
    EXPECT_EQ(machine.spindleState(), machine::SpindleState::Forward);
    EXPECT_DOUBLE_EQ(machine.position()(2), stoppedAt(2));
}

TEST(HoldMotion, StartBringsTheAxesBackWherePauseNcTookThemAtTheHigherZ) {
    params::ParameterTable p;
    SimulatedMachine machine;
    HoldMotion hold(machine, p);
    hold.held({});
    const machine::Axes stoppedAt = machine.position();
    machine::Axes parked = stoppedAt;
    parked(0) = 40.0;
    parked(2) = 30.0;
    machine.rapid(parked); // what pause.nc did
    hold.pauseHookRan(stoppedAt);

    hold.resume();
    EXPECT_TRUE(((machine.position() - stoppedAt).cwiseAbs().maxCoeff()) < 1e-9);
}

TEST(HoldMotion, ResetForgetsTheLiftTheSpindleAndTheRest) {
    const params::ParameterTable p = stopAndLift15();
    SimulatedMachine machine;
    HoldMotion hold(machine, p);
    hold.held(cutShort(machine));
    const machine::Axes lifted = machine.position();

    hold.forget();
    const HoldMotion::Finished finished = hold.resume();
    EXPECT_FALSE(finished.cut);
    EXPECT_EQ(machine.spindleState(), machine::SpindleState::Stop);
    EXPECT_TRUE(((machine.position() - lifted).cwiseAbs().maxCoeff()) < 1e-9) << "nothing moves";
}

} // namespace
