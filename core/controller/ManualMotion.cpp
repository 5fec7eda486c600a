// The operator's manual motion: the jog keys (连续 CONT, 寸动 STEP), the handwheel in MPG mode,
// the manual and spindle overrides, and the IO page's output switches.
#include "core/controller/Controller.h"

#include "core/params/ParameterNumbers.h"
#include "core/controller/ManualParameters.h"
#include "core/macro/MacroError.h"

#include <algorithm>
#include <cmath>

namespace m350::controller {


namespace {

bool validAxis(int axis) { return axis >= 0 && axis < machine::kAxisCount; }

} // namespace

bool Controller::manualAllowed() const {
    return state_ != RunState::Running && state_ != RunState::Hold && state_ != RunState::Alarm &&
           state_ != RunState::EStop;
}

bool Controller::jogging() const { return displayTime_ < std::min(manual_.movingUntil, machine_.time()); }

void Controller::setJogMode(JogMode mode) {
    if (manual_.heldAxis >= 0) {
        jogRelease(manual_.heldAxis);
    }
    manual_.mode = mode;
}

void Controller::setJogStep(double distance) {
    if (std::isfinite(distance) && distance > 0.0) {
        manual_.step = distance;
    }
}

void Controller::setJogHighSpeed(bool high) { manual_.highSpeed = high; }

double Controller::setJogOverride(double percent) {
    double maximum = config_.parameters.get(param::kMaxFeedOverride);
    manual_.jogOverride = std::clamp(std::isfinite(percent) ? percent : 100.0, 0.0, maximum > 0.0 ? maximum : 150.0);
    return manual_.jogOverride;
}

bool Controller::jogPress(int axis, int direction) {
    if (!manualAllowed() || !validAxis(axis) || (direction != 1 && direction != -1) ||
        manual_.mode == JogMode::Mpg) {
        return false;
    }
    if (manual_.heldAxis >= 0) {
        jogRelease(manual_.heldAxis); // one CONT key at a time
    }
    const params::ParameterTable& p = config_.parameters;
    double speed = std::min(manual::jogSpeed(p, axis, manual_.highSpeed) * manual_.jogOverride / 100.0,
                            manual::maxManualSpeed(p, axis));
    if (speed <= 0.0) {
        return false; // SJR at 0 %
    }
    bool continuous = manual_.mode == JogMode::Continuous;
    double distance = direction * (continuous ? kJogTravel : manual_.step);
    if (!moveManually(axis, distance, speed / 60.0, manual::startAcceleration(p, axis))) {
        return false;
    }
    if (continuous) {
        manual_.heldAxis = axis;
    }
    return true;
}

void Controller::jogRelease(int axis) {
    if (manual_.heldAxis != axis) {
        return; // a STEP runs its increment to the end
    }
    manual_.heldAxis = -1;
    machine_.brake(displayTime_, manual::stopAcceleration(config_.parameters, axis));
    manual_.movingUntil = machine_.time();
}

bool Controller::wheelTurn(int axis, int multiplier, int detents, double seconds) {
    const params::ParameterTable& p = config_.parameters;
    const double wheelSpeed = manual::mpgSpeed(p, multiplier);
    if (!validAxis(axis) || wheelSpeed <= 0.0 || detents == 0 || !std::isfinite(seconds) || seconds <= 0.0) {
        return false;
    }
    const bool runOn = state_ == RunState::Running || (state_ == RunState::Finished && displayTime_ < machine_.time());
    if (manual_.guide && runOn) {
        return guideTurn(multiplier, detents, seconds);
    }
    if (manual_.mode != JogMode::Mpg || !manualAllowed()) {
        return false;
    }
    double distance = detents * multiplier * manual::mpgDistance(p) * (manual::mpgReversed(p) ? -1.0 : 1.0);
    // the motion follows the wheel: no faster than it was turned, nor than the wheel's speed
    double speed = std::min({wheelSpeed / 60.0, manual::maxManualSpeed(p, axis) / 60.0, std::abs(distance) / seconds});
    return moveManually(axis, distance, speed, manual::mpgAcceleration(p, axis));
}

// One manual move of `axis` by `distance`, stopped at the soft limits when they are on (an axis
// already beyond one may still come back). False when nothing can move.
bool Controller::moveManually(int axis, double distance, double speed, double acceleration) {
    if (machine_.time() < displayTime_) {
        machine_.blockTime(displayTime_ - machine_.time()); // the machine stood still until now
    }
    const params::ParameterTable& p = config_.parameters;
    const machine::Axes from = machine_.position();
    machine::Axes target = from;
    target(axis) += distance;
    if (manual::softLimitsOn(p)) {
        manual::Travel travel = manual::softLimits(p, axis);
        target(axis) = std::clamp(target(axis), std::min(travel.low, from(axis)), std::max(travel.high, from(axis)));
    }
    if (std::abs(target(axis) - from(axis)) < 1e-9) {
        return false;
    }
    try {
        machine_.manualMove(target, speed, acceleration);
    } catch (const macro::MacroError& error) {
        raiseAlarm(Alarm{error.code, error.message, "", 0, 0}); // the magazine was hit
        return false;
    }
    manual_.movingUntil = machine_.time();
    return true;
}

double Controller::setSpindleOverride(double percent) {
    manual_.spindleOverride = std::clamp(std::isfinite(percent) ? percent : 100.0, 50.0, 150.0);
    return manual_.spindleOverride;
}

bool Controller::setOutputByOperator(int port, int level) {
    if (port < 1 || port > machine::kOutputCount || (level != 0 && level != 1) || state_ == RunState::Running ||
        state_ == RunState::Hold || state_ == RunState::EStop) {
        return false;
    }
    if (machine_.time() < displayTime_) {
        machine_.blockTime(displayTime_ - machine_.time());
    }
    try {
        machine_.setOutput(port, level);
    } catch (const macro::MacroError& error) {
        raiseAlarm(Alarm{error.code, error.message, "", 0, 0}); // the output switched; the magazine suffered it
    }
    return true;
}

} // namespace m350::controller
