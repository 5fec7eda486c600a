#include "core/controller/HoldMotion.h"

#include "core/controller/ContinueRemainder.h"
#include "core/params/ParameterNumbers.h"
#include "core/params/ParameterTable.h"

#include <algorithm>

namespace m350::controller {

namespace {

bool movedAwayFrom(const machine::Axes& from, const machine::Axes& to) {
    return (from - to).cwiseAbs().maxCoeff() > 1e-9;
}

} // namespace

HoldMotion::HoldMotion(machine::SimulatedMachine& machine, const params::ParameterTable& parameters)
    : machine_(machine), parameters_(parameters) {}

void HoldMotion::held(const machine::SimulatedMachine::Remainder& rest) {
    remainder_ = rest;
    const params::ParameterTable& p = parameters_;
    if (p.get(param::kStopSpindleOnPause) != 0.0 && machine_.spindleState() != machine::SpindleState::Stop) {
        spindleBeforeHold_ = std::make_pair(machine_.spindleState(), machine_.spindleRpm());
        machine_.spindle(machine::SpindleState::Stop, 0.0);
    }
    liftedBy_ = p.get(param::kPauseZMode) != 0.0 ? std::max(0.0, p.get(param::kPauseLift)) : 0.0;
    if (liftedBy_ > 0.0) {
        machine::Axes up = machine_.position();
        up(2) += liftedBy_;
        machine_.rapid(up);
    }
}

void HoldMotion::pauseHookRan(const machine::Axes& stoppedAt) {
    if (movedAwayFrom(stoppedAt, machine_.position())) {
        beforePauseHook_ = stoppedAt;
    }
}

HoldMotion::Finished HoldMotion::resume() {
    returnAfterPauseHook();
    if (liftedBy_ > 0.0) {
        machine::Axes down = machine_.position();
        down(2) -= liftedBy_;
        machine_.rapid(down);
        liftedBy_ = 0.0;
    }
    if (spindleBeforeHold_) {
        machine_.spindle(spindleBeforeHold_->first, spindleBeforeHold_->second);
        spindleBeforeHold_.reset();
    }
    Finished finished;
    finished.from = machine_.time();
    continueRemainder(machine_, remainder_);
    finished.cut = remainder_.kind == machine::SimulatedMachine::Remainder::Kind::Feed ||
                   remainder_.kind == machine::SimulatedMachine::Remainder::Kind::Arc;
    remainder_ = {};
    return finished;
}

// Z up to the higher of the two, over at that height, then down to where the hold stopped.
void HoldMotion::returnAfterPauseHook() {
    if (!beforePauseHook_) {
        return;
    }
    const machine::Axes back = *beforePauseHook_;
    beforePauseHook_.reset();
    machine::Axes step = machine_.position();
    const double safeZ = std::max(step(2), back(2));
    for (int stage = 0; stage < 3; ++stage) {
        machine::Axes target = stage == 0 ? step : back;
        target(2) = stage == 2 ? back(2) : safeZ;
        if (movedAwayFrom(machine_.position(), target)) {
            machine_.rapid(target);
        }
    }
}

void HoldMotion::forget() {
    remainder_ = {};
    liftedBy_ = 0.0;
    beforePauseHook_.reset();
    spindleBeforeHold_.reset();
}

} // namespace m350::controller
