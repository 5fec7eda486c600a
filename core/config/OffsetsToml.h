#pragma once

#include "core/config/MachineConfig.h"

#include <filesystem>

namespace m350::config {

// The folder's offsets.toml, when there is one: G92, G54-G59, G52 and the common offset, each a
// list of up to five axes. Fails with file:line:col; fewer than three axes are said.
void loadOffsets(const std::filesystem::path& folder, MachineConfig& config);

} // namespace m350::config
