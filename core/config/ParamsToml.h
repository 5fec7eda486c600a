#pragma once

#include "core/config/MachineConfig.h"

#include <filesystem>

namespace m350::config {

// The folder's params.toml [params] over the factory values (an M350's catalogue defaults; a FANUC
// has none): 0-999, and a FANUC's 1000-99999 with where each came from; then the call codes rebuilt
// from [codes] and FANUC's 6050-6091. A refused value fails with file:line:col; one the panel
// would refuse is kept and said.
void loadParams(const std::filesystem::path& folder, MachineConfig& config);

} // namespace m350::config
