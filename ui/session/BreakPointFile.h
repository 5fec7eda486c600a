#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QString>

#include <optional>
#include <utility>

namespace m350::config {
class MachineFolder;
}
namespace m350::controller {
class BreakRun;
}

namespace m350::ui {

// The machine folder's `breakpoint` file (断点加工): after a pause or a reset mid-run the break
// point goes there, so that a restart of the panel can resume where the run stopped.
class BreakPointFile {
public:
    // Writes the break point of a pause or a reset mid-run, if there is one; why not, if it failed.
    std::optional<QString> keep(const controller::BreakRun& run, const config::MachineFolder& folder);
    // The pause's break point and the one the folder keeps (read once, then as written).
    BreakPoints points(const controller::BreakRun& run, const config::MachineFolder& folder) const;

private:
    mutable std::optional<std::pair<QString, int>> kept_;
};

} // namespace m350::ui
