#pragma once

#include "core/common/Alarm.h"
#include "core/config/MachineConfig.h"
#include "core/gcode/Diagnostic.h"
#include "core/preview/PathLevels.h"
#include "core/preview/PathStore.h"

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace m350::preview {

struct PreviewSettings {
    // The most moves the preview keeps (20 bytes each, 8 more an arc): past it the path is merged
    // to a coarser tolerance, again and again, so a program of any size previews in bounded memory.
    std::size_t segmentBudget = 12'000'000;
    double maxSimTime = 1e7; // virtual seconds: a preview of an endless loop ends
    // Set (from another thread) when nobody wants the preview any more: the build stops at its
    // next few thousand moves and returns what it has, marked cancelled.
    const std::atomic<bool>* cancel = nullptr;
    std::optional<int> tool; // in the spindle at start (a change to it makes no moves)
};

// What the machine view draws of a program: every move its run makes (the machine's libraries
// and tool changes included), in machine coordinates, with the line each comes from.
struct Preview {
    PathStore path;
    PathLevels levels;
    bool loaded = false;                      // false: a syntax error; diagnostics say which
    std::vector<gcode::Diagnostic> diagnostics;
    std::optional<Alarm> alarm;               // the run stopped there: the path is up to it
    double coarsenedTo = 0.0;                 // > 0: the budget was reached, the path is within this many mm
    std::size_t moves = 0;                    // moves the run made (more than path.size() once coarsened)
    bool cancelled = false;                   // PreviewSettings::cancel stopped it: the path is a part

    std::size_t bytes() const { return path.bytes() + levels.bytes(); }
};

// Runs `program` on a controller of its own (it never moves a machine anyone drives) as fast as the
// core goes, and keeps the moves. For a thread of its own: it shares nothing.
Preview buildPreview(config::MachineConfig config, const std::string& program, const PreviewSettings& settings = {});

} // namespace m350::preview
