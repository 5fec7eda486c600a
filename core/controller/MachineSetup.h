#pragma once

#include "core/config/MachineConfig.h"

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::controller {

// The simulated machine as the parameters as they stand set it up: rapid and feed speeds and
// accelerations, the spindle's delays and top speed, the home switches, the fixed setter (param
// 130's input, X/Y, the folder's top and radius), the floating setter, the spindle-stopped sensor.
// True when the fixed setter is wired: a rapid into it is then a crash the machine's observer sees.
bool setUpMachine(machine::SimulatedMachine& simulated, const config::MachineConfig& config);

} // namespace m350::controller
