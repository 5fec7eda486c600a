#pragma once

#include "core/config/MachineFolder.h"
#include "core/files/AtomicFile.h"

#include <map>
#include <optional>
#include <string>

namespace m350::controller {

class Controller;

// Saves the controller's tool data into the machine folder (tool.tbl, and on the M350 the Z
// parameters params.toml lists: config::MachineFolder::saveToolTable) and marks it saved, so that
// ToolTableEdits::changed() turns false. nullopt on success, else why (the data stays unsaved).
std::optional<Message> saveToolTable(Controller& controller, const config::MachineFolder& folder,
                                         const files::AtomicWriteHooks& hooks = {});

// Parameters the panel set (or a run wrote) into params.toml; when the tool data changed too (on
// the M350 a tool's Z is parameter 930-945 or 973-992), tool.tbl is saved with them as one change,
// so a crash never leaves the two files disagreeing. nullopt on success, else why.
std::optional<Message> saveParameters(Controller& controller, const config::MachineFolder& folder,
                                          const std::map<int, double>& values, const files::AtomicWriteHooks& hooks = {});

} // namespace m350::controller
