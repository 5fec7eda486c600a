#pragma once

#include "core/config/MachineConfig.h"

#include "core/files/Toml.h"

#include <filesystem>

namespace m350::config {

// Reads machine.toml's FANUC options, what the control in the machine was sold with:
//   [variables]   common = ["100-499", "500-999", "98000-98499"]   the common variables (a range
//                 below #500 is cleared at reset, the others are kept: variables.toml)
//   [coordinates] additional_systems = 300   G54.1 P1-P300 (0i: 48; 0: none)
//                 rotation = true            G68 / G69
// into config.variableLayout and config.coordinateRotation; a bad value fails with file:line:col,
// and so does any of them on an M350 (its variables and G codes are fixed).
void readControlOptions(const std::filesystem::path& file, const toml::table& machine, MachineConfig& config);

} // namespace m350::config
