#pragma once

#include "app/sim/SimOptions.h"

#include "core/config/MachineConfig.h"

#include <optional>
#include <string>

namespace m350::sim {

// Where the run's DPRNT output goes: --dprnt FILE, else dprnt.txt beside the program (run) or in
// the current folder (mdi, hook).
std::string externalOutputPath(const SimOptions& o);

// An output option (--trace, --dprnt, --tools-out, or the default dprnt.txt) that names a file the
// run reads (the program, a library, a machine-folder file, --tool-table): why it is refused. Said
// before anything is opened for writing: `--trace prog.nc` emptied the program and exited 0.
std::optional<Message> outputNamingAnInput(const SimOptions& o, const config::MachineConfig& machine);

} // namespace m350::sim
