// The operator's manual motion: the jog keys (连续 CONT, 寸动 STEP), the handwheel in MPG mode,
// the manual and spindle overrides, and the IO page's output switches.
//
// 试切 handwheel-guided run: the program's time follows the wheel through GuideOverride; turning
// backwards holds or retraces the moves already made (SimulatedMachine keeps them while the guide
// is on). A retrace moves the axes only: the blocks behind it are not undone (outputs, spindle,
// variables stay as they were set), and turning forward replays the path before new blocks run.
#include "core/controller/ManualControl.h"

#include "core/controller/ManualParameters.h"
#include "core/controller/RunView.h"
#include "core/macro/MacroError.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace m350::controller {

namespace {

bool validAxis(int axis) { return axis >= 0 && axis < machine::kAxisCount; }

} // namespace

ManualControl::ManualControl(machine::SimulatedMachine& machine, const params::ParameterTable& parameters, RunView& run)
    : machine_(machine), parameters_(parameters), run_(run) {}

bool ManualControl::manualAllowed() const {
    const RunState state = run_.runState();
    return state != RunState::Running && state != RunState::Hold && state != RunState::Alarm &&
           state != RunState::EStop;
}

bool ManualControl::jogging() const { return run_.displayTime() < std::min(state_.movingUntil, machine_.time()); }

void ManualControl::setJogMode(JogMode mode) {
    if (state_.heldAxis >= 0) {
        jogRelease(state_.heldAxis);
    }
    state_.mode = mode;
}

void ManualControl::setJogStep(double distance) {
    if (std::isfinite(distance) && distance > 0.0) {
        state_.step = distance;
    }
}

void ManualControl::setJogHighSpeed(bool high) { state_.highSpeed = high; }

double ManualControl::setJogOverride(double percent) {
    double maximum = parameters_.get(param::kMaxFeedOverride);
    state_.jogOverride = std::clamp(std::isfinite(percent) ? percent : 100.0, 0.0, maximum > 0.0 ? maximum : 150.0);
    return state_.jogOverride;
}

bool ManualControl::jogPress(int axis, int direction) {
    if (!manualAllowed() || !validAxis(axis) || (direction != 1 && direction != -1) ||
        state_.mode == JogMode::Mpg) {
        return false;
    }
    if (state_.heldAxis >= 0) {
        jogRelease(state_.heldAxis); // one CONT key at a time
    }
    const params::ParameterTable& p = parameters_;
    double speed = std::min(manual::jogSpeed(p, axis, state_.highSpeed) * state_.jogOverride / 100.0,
                            manual::maxManualSpeed(p, axis));
    if (speed <= 0.0) {
        return false; // SJR at 0 %
    }
    bool continuous = state_.mode == JogMode::Continuous;
    double distance = direction * (continuous ? kJogTravel : state_.step);
    if (!moveManually(axis, distance, speed / 60.0, manual::startAcceleration(p, axis))) {
        return false;
    }
    if (continuous) {
        state_.heldAxis = axis;
    }
    return true;
}

void ManualControl::jogRelease(int axis) {
    if (state_.heldAxis != axis) {
        return; // a STEP runs its increment to the end
    }
    state_.heldAxis = -1;
    machine_.brake(run_.displayTime(), manual::stopAcceleration(parameters_, axis));
    state_.movingUntil = machine_.time();
}

bool ManualControl::wheelTurn(int axis, int multiplier, int detents, double seconds) {
    const params::ParameterTable& p = parameters_;
    const double wheelSpeed = manual::mpgSpeed(p, multiplier);
    if (!validAxis(axis) || wheelSpeed <= 0.0 || detents == 0 || !std::isfinite(seconds) || seconds <= 0.0) {
        return false;
    }
    const RunState state = run_.runState();
    const bool runOn =
        state == RunState::Running || (state == RunState::Finished && run_.displayTime() < machine_.time());
    if (state_.guide && runOn) {
        return guideTurn(multiplier, detents, seconds);
    }
    if (state_.mode != JogMode::Mpg || !manualAllowed()) {
        return false;
    }
    double distance = detents * multiplier * manual::mpgDistance(p) * (manual::mpgReversed(p) ? -1.0 : 1.0);
    // the motion follows the wheel: no faster than it was turned, nor than the wheel's speed
    double speed = std::min({wheelSpeed / 60.0, manual::maxManualSpeed(p, axis) / 60.0, std::abs(distance) / seconds});
    const double acceleration = manual::mpgAcceleration(p, axis);
    if (!manual::mpgPrecise(p)) {
        // param 171 = 1: the pulses the axis cannot run while the wheel turns are dropped, so the
        // axis is at rest when the turn ends
        const double now = run_.displayTime();
        const double window = now + seconds - std::max(machine_.time(), now);
        const double reach = reachWithin(window, speed, acceleration);
        if (reach <= 0.0) {
            return false;
        }
        distance = std::copysign(std::min(std::abs(distance), reach), distance);
    }
    return moveManually(axis, distance, speed, acceleration);
}

// How far a move from rest to rest, at most `speed` and ramping at `acceleration`, gets in `seconds`.
double ManualControl::reachWithin(double seconds, double speed, double acceleration) {
    if (seconds <= 0.0 || speed <= 0.0) {
        return 0.0;
    }
    if (acceleration <= 0.0) {
        return speed * seconds;
    }
    const double ramps = 2.0 * speed / acceleration;
    return seconds >= ramps ? speed * seconds - speed * speed / acceleration : acceleration * seconds * seconds / 4.0;
}

// One manual move of `axis` by `distance`, stopped at the soft limits when they are on and the
// axis is homed (an axis already beyond one may still come back). False when nothing can move.
bool ManualControl::moveManually(int axis, double distance, double speed, double acceleration) {
    const double now = run_.displayTime();
    if (machine_.time() < now) {
        machine_.blockTime(now - machine_.time()); // the machine stood still until now
    }
    const params::ParameterTable& p = parameters_;
    const machine::Axes from = machine_.position();
    machine::Axes target = from;
    target(axis) += distance;
    if (manual::softLimitsOn(p) && run_.axisHomed(axis)) {
        manual::Travel travel = manual::softLimits(p, axis);
        target(axis) = std::clamp(target(axis), std::min(travel.low, from(axis)), std::max(travel.high, from(axis)));
    }
    if (std::abs(target(axis) - from(axis)) < 1e-9) {
        return false;
    }
    try {
        machine_.manualMove(target, speed, acceleration);
    } catch (const macro::MacroError& error) {
        run_.raiseAlarm(Alarm{error.code, error.message, "", 0, 0, {}, 0, error.messageId, error.messageArguments}); // the magazine or the setter was hit
        return false;
    }
    state_.movingUntil = machine_.time();
    return true;
}

double ManualControl::setSpindleOverride(double percent) {
    state_.spindleOverride = std::clamp(std::isfinite(percent) ? percent : 100.0, 50.0, 150.0);
    return state_.spindleOverride;
}

bool ManualControl::setOutputByOperator(int port, int level) {
    const RunState state = run_.runState();
    if (port < 1 || port > machine::kOutputCount || (level != 0 && level != 1) || state == RunState::Running ||
        state == RunState::Hold || state == RunState::EStop) {
        return false;
    }
    const double now = run_.displayTime();
    if (machine_.time() < now) {
        machine_.blockTime(now - machine_.time());
    }
    try {
        machine_.setOutput(port, level);
    } catch (const macro::MacroError& error) {
        run_.raiseAlarm(Alarm{error.code, error.message, "", 0, 0, {}, 0, error.messageId,
                              error.messageArguments}); // the output switched; the magazine suffered it
    }
    return true;
}

bool ManualControl::spindleJog(bool on) {
    const RunState state = run_.runState();
    if (state == RunState::Running || state == RunState::Hold) {
        return false;
    }
    if (on) {
        machine_.spindle(machine::SpindleState::Jog, parameters_.get(param::kDefaultSpindleSpeed));
    } else if (machine_.spindleState() == machine::SpindleState::Jog) {
        machine_.spindle(machine::SpindleState::Stop, 0.0);
    }
    return true;
}

void ManualControl::setHandwheelGuide(bool on) {
    if (on == state_.guide) {
        return;
    }
    state_.guide = on;
    state_.override.reset();
    if (on) {
        machine_.setKeepHistory(true);
    }
    // off: the moves are kept until the display has caught up with them (displayStep)
}

// The wheel's speed as a fraction of the handwheel speed at its multiplier (params 176-178) is
// the override it asks for: 100 % when it turns as fast as an MPG jog at that multiplier moves,
// capped at param 295 (100 % when 0).
bool ManualControl::guideTurn(int multiplier, int detents, double seconds) {
    const params::ParameterTable& p = parameters_;
    double wheel = std::abs(detents) * multiplier * manual::mpgDistance(p) / seconds;
    double full = manual::mpgSpeed(p, multiplier) / 60.0;
    double maximum = p.get(param::kMaxFeedOverride) > 0.0 ? p.get(param::kMaxFeedOverride) / 100.0 : 1.0;
    double target = std::min(wheel / full, maximum);
    int direction = (detents > 0) != manual::mpgReversed(p) ? 1 : -1;
    bool hold = direction < 0 && state_.reverse == GuideReverse::Hold;
    state_.override.turn(direction, hold ? 0.0 : direction * target, seconds);
    return true;
}

double ManualControl::displayStep(double seconds) {
    const RunState state = run_.runState();
    const double now = run_.displayTime();
    const bool behind = now < machine_.time();
    if (state_.guide && state == RunState::Hold) {
        state_.override.reset();
        return 0.0; // held: the program's time stands, wherever the wheel had taken it
    }
    bool drives = state_.guide && std::isfinite(seconds) &&
                  (state == RunState::Running || (state == RunState::Finished && behind));
    if (!drives) {
        if (!state_.guide && machine_.keepsHistory() && now + seconds >= machine_.moveStart()) {
            machine_.setKeepHistory(false); // caught up with what a retrace left behind
        }
        return seconds;
    }
    const params::ParameterTable& p = parameters_;
    double step = state_.override.advance(seconds, {manual::guideChangeStep(p), manual::guideStopStep(p)});
    double floor = std::max(machine_.historyFrom(), run_.runStartedAt()); // no further back than the kept moves
    return std::max(step, std::min(0.0, floor - now));
}

} // namespace m350::controller
