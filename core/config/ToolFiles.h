#pragma once

#include "core/config/MachineConfig.h"

#include <filesystem>

namespace m350::config {

// The folder's tool.tbl, when there is one: a refused line is a warning (the rest loads); on the
// M350 the table's Z replaces the tool's parameter and a different non-zero value in params.toml
// is said. An unreadable file fails.
void loadToolTable(const std::filesystem::path& folder, MachineConfig& config);
// The folder's toollife.txt (FANUC tool life management; a FANUC's parameters 6800 ... set its
// limits): a refused line is a warning; an unreadable file fails.
void loadToolLifeFile(const std::filesystem::path& folder, MachineConfig& config);

} // namespace m350::config
