#pragma once

#include "core/config/MachineConfig.h"

#include <filesystem>

namespace m350::config {

// The folder's machine.toml into `config`: its name and dialect, [libraries] (LibrariesToml),
// [codes], [io_links], [magazine] (MagazineToml), [homing], the setters, the tools (ToolsToml),
// the spindle load's world (SpindleLoadToml), a FANUC's [interface_signals], [variables] and
// [coordinates] (ControlOptionsToml), [reference_points]. Fails (toml_reading::fail) with
// file:line:col; keys nobody reads are warned of.
void loadMachineToml(const std::filesystem::path& folder, MachineConfig& config);

} // namespace m350::config
