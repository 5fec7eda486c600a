#pragma once

#include "core/backup/ControllerBackup.h"
#include "core/gcode/Diagnostic.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::backup {

// A backup's `mdiblock` as the panel keeps it (ui/pages/MdiLines: six records of 120 bytes, each
// a line padded with NULs): the line bytes kept exactly (GBK stays GBK), what follows a record's
// first NUL cleared, a short file padded. The lines decoded to UTF-8 for reports and `m350-sim mdi`.
struct ImportedMdi {
    std::string bytes;
    std::vector<std::string> lines;
    std::optional<Message> note; // what was not as the panel writes it
};
ImportedMdi importMdiBlock(const std::string& raw);

// The syntax errors the m350 dialect finds in the backup's .nc files: the libraries parsed
// together as the controller loads them, every other file on its own. A library with one stops
// every program of the machine; a hook file with one stops only itself.
std::vector<gcode::Diagnostic> checkPrograms(const ControllerBackup& backup, const std::vector<std::string>& libraries);

} // namespace m350::backup
