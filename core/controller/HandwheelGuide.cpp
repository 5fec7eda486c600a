// 试切 handwheel-guided run: the program's time follows the wheel through GuideOverride; turning
// backwards holds or retraces the moves already made (SimulatedMachine keeps them while the guide
// is on). A retrace moves the axes only: the blocks behind it are not undone (outputs, spindle,
// variables stay as they were set), and turning forward replays the path before new blocks run.
#include "core/controller/Controller.h"

#include "core/params/ParameterNumbers.h"
#include "core/controller/ManualParameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace m350::controller {


void Controller::setHandwheelGuide(bool on) {
    if (on == manual_.guide) {
        return;
    }
    manual_.guide = on;
    manual_.override.reset();
    if (on) {
        machine_.setKeepHistory(true);
    }
    // off: the moves are kept until the display has caught up with them (displayStep)
}

// The wheel's speed as a fraction of the handwheel speed at its multiplier (params 176-178) is
// the override it asks for: 100 % when it turns as fast as an MPG jog at that multiplier moves,
// capped at param 295 (100 % when 0).
bool Controller::guideTurn(int multiplier, int detents, double seconds) {
    const params::ParameterTable& p = config_.parameters;
    double wheel = std::abs(detents) * multiplier * manual::mpgDistance(p) / seconds;
    double full = manual::mpgSpeed(p, multiplier) / 60.0;
    double maximum = p.get(param::kMaxFeedOverride) > 0.0 ? p.get(param::kMaxFeedOverride) / 100.0 : 1.0;
    double target = std::min(wheel / full, maximum);
    int direction = (detents > 0) != manual::mpgReversed(p) ? 1 : -1;
    bool hold = direction < 0 && manual_.reverse == GuideReverse::Hold;
    manual_.override.turn(direction, hold ? 0.0 : direction * target, seconds);
    return true;
}

// How far the display time moves for `seconds` of the panel's time: as much, unless the guide
// drives the run. advance(infinity) (run(), no operator) runs without the wheel.
double Controller::displayStep(double seconds) {
    const bool behind = displayTime_ < machine_.time();
    if (manual_.guide && state_ == RunState::Hold) {
        manual_.override.reset();
        return 0.0; // held: the program's time stands, wherever the wheel had taken it
    }
    bool drives = manual_.guide && std::isfinite(seconds) &&
                  (state_ == RunState::Running || (state_ == RunState::Finished && behind));
    if (!drives) {
        if (!manual_.guide && machine_.keepsHistory() && displayTime_ + seconds >= machine_.moveStart()) {
            machine_.setKeepHistory(false); // caught up with what a retrace left behind
        }
        return seconds;
    }
    const params::ParameterTable& p = config_.parameters;
    double step = manual_.override.advance(seconds, {manual::guideChangeStep(p), manual::guideStopStep(p)});
    double floor = std::max(machine_.historyFrom(), runStartedAt_); // no further back than the kept moves
    return std::max(step, std::min(0.0, floor - displayTime_));
}

} // namespace m350::controller
