#pragma once

#include "core/config/MachineConfig.h"

#include <filesystem>

namespace m350::config {

// The folder's variables.toml, when there is one: [variables] number = value, set before a run. A
// bad number or value fails with file:line:col; a variable the dialect does not have is said and left out.
void loadVariables(const std::filesystem::path& folder, MachineConfig& config);

} // namespace m350::config
