#pragma once

#include "core/training/AttemptFacts.h"
#include "core/training/Exercise.h"

namespace m350::controller {
class Controller;
}

namespace m350::training {

// The end of an attempt as the exercise's checks will read it: the spindle, the pockets, the
// outputs, and the parameters, variables and tool offsets the checks name; the machine's events
// with their times counted from `attemptStart` (the machine's virtual time when the attempt began).
// The machine's virtual time now: when an attempt begins, the time its events count from.
double attemptClock(const controller::Controller& controller);

AttemptFacts factsFromController(controller::Controller& controller, const Exercise& exercise, double attemptStart,
                                 const std::string& machineFolder);

} // namespace m350::training
