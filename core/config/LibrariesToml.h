#pragma once

#include "core/config/MachineConfig.h"

#include "core/files/Toml.h"

#include <filesystem>

namespace m350::config {

// machine.toml's [libraries] (g, m, other: the machine's macro libraries, each a file of the
// machine folder, a bundled machine folder, a sibling machine folder or the folder M350_LIBRARIES
// names), then the folder's slibuser.nc beside them. `file` is machine.toml; a library that is not
// a name, lies elsewhere, is missing or is no file fails with file:line:col.
void readLibraries(const std::filesystem::path& folder, const std::filesystem::path& file, const toml::table& machine,
                   MachineConfig& config);

} // namespace m350::config
