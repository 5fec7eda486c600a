#pragma once

#include "core/controller/SpindleLoadWatch.h"

#include <nlohmann/json.hpp>

namespace m350::sim {

// The run JSON's "spindle_load" (on machines with a load model): lambda, the register variable,
// the monitor's rule and limits, how many samples were taken and the last ones (at most
// SpindleLoadMonitor::kHistory) as [time s, tool, load %].
nlohmann::json spindleLoadJson(const controller::SpindleLoadWatch& watch, bool fanuc);

} // namespace m350::sim
