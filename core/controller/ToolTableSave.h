#pragma once

#include "core/config/MachineFolder.h"
#include "core/files/AtomicFile.h"

#include <optional>
#include <string>

namespace m350::controller {

class Controller;

// Saves the controller's tool data into the machine folder (tool.tbl, and on the M350 the Z
// parameters params.toml lists: config::MachineFolder::saveToolTable) and marks it saved, so that
// ToolTableEdits::changed() turns false. nullopt on success, else why (the data stays unsaved).
std::optional<std::string> saveToolTable(Controller& controller, const config::MachineFolder& folder,
                                         const files::AtomicWriteHooks& hooks = {});

} // namespace m350::controller
