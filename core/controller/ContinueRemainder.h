#pragma once

#include "core/machine/SimulatedMachine.h"

namespace m350::controller {

// The rest of what a hold cut short: the move to its end (an arc about the same center, from
// where it stopped) or the dwell's remaining time. RESUME and a break run's start from the stop
// point both finish it.
void continueRemainder(machine::SimulatedMachine& simulated, const machine::SimulatedMachine::Remainder& rest);

} // namespace m350::controller
