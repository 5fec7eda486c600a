#pragma once

#include "app/sim/SimOptions.h"

#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"

#include <optional>
#include <string>

namespace m350::sim {

// What the command runs, loaded into the controller: the program, the MDI lines or the hook file.
bool loadForCommand(controller::Controller& controller, const SimOptions& o);

// `hook NAME` on a machine folder without that file: the usage message, naming the hook files the
// folder has.
std::optional<Message> missingHook(const SimOptions& o, const config::MachineConfig& machine);

// --home: the folder's fndzero.nc run to its end when it has one (as the panel's Go Home does),
// else the native homing of every axis with a switch. The report when homing fails.
std::optional<controller::RunReport> homeBeforeRun(controller::Controller& controller);

} // namespace m350::sim
