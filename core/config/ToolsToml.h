#pragma once

#include "core/config/MachineConfig.h"

#include "core/files/Toml.h"

#include <filesystem>

namespace m350::config {

// machine.toml's tools: [tools] length and diameter (lists from T1), [tools.N] (one tool beyond the
// lists), [tool_data] (offset_memory, random_changer). A bad value fails with file:line:col.
void readTools(const std::filesystem::path& file, const toml::table& machine, MachineConfig& config);

} // namespace m350::config
