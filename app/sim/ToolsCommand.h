#pragma once

#include "app/sim/SimOptions.h"

#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"

#include <optional>
#include <string>

namespace m350::sim {

// --tool-table FILE: that tool.tbl replaces the machine folder's for this run (its refused lines
// are printed as warnings with file:line:col, the rest loads). The error when it cannot be read.
std::optional<Message> useToolTableFile(const SimOptions& o, config::MachineConfig& machine);

// `m350-sim tools`: the machine's tool table as a run starts with it (the folder's tool.tbl, or
// --tool-table; on the M350 the Z of T1-T16 and the virtual tools from params 930-945 / 973-992).
// One JSON object, or the table in tool.tbl form with --tbl. Exit 2 when lines were skipped.
int listTools(controller::Controller& controller, const SimOptions& o);

// --tools-out FILE after run / mdi / hook: the tool table as the run left it, written atomically.
std::optional<Message> exportTools(controller::Controller& controller, const SimOptions& o);

} // namespace m350::sim
