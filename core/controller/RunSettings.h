#pragma once

#include "core/gcode/SourceText.h"
#include "core/machine/InputFault.h"
#include "core/machine/ToolWorld.h"
#include "core/params/ParameterPages.h"
#include "core/tools/SpindleLoadLimits.h"

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <vector>

namespace m350::machine {
class MachineObserver;
}

namespace m350::controller {

// How one run is set up, beyond the machine folder (the `m350-sim` options).
struct RunSettings {
    double maxSimTime = 3600.0; // virtual seconds before a runaway program is stopped
    double blockTime = 1e-4;    // virtual seconds one block costs to prepare (macro statements too)
    // A macro line that keeps reading a sensor input unchanged for this long raises an alarm naming
    // the input, instead of waiting forever (the real machine would hang there).
    double sensorTimeout = 10.0;
    bool homed = true;
    bool optionalStop = false;  // the M01 switch (on the M350 #1500 = 1 turns it on too)
    bool singleBlock = false;   // the single block switch (Controller::setSingleBlock)
    // The user level the run's MDI lines and program write parameters with (m350-sim --level):
    // Super, as nobody stands at a panel, unless told (Controller::setUserLevel).
    params::UserLevel userLevel = params::UserLevel::Super;
    // run() presses PAUSE when the run has gone this many seconds of virtual time, and START once
    // the machine stands (m350-sim --pause-at).
    std::optional<double> pauseAt;
    // run() presses 急停 when the run has gone this many seconds (m350-sim --estop-at).
    std::optional<double> estopAt;
    // A person at the panel (the panel sets it): a #1505 dialog holds the run until answered
    // (Controller::answerDialog). Without one, run() answers every dialog with Enter.
    bool operatorPresent = false;
    std::optional<int> tool;    // tool in the spindle at start
    std::map<int, int> heldInputs;     // port -> level for the whole run
    std::map<int, machine::InputFault> inputFaults; // port -> a fault for the whole run (a late setter signal)
    std::map<int, double> parameters;  // overrides of the machine folder's parameters
    std::map<int, double> variables;   // set before the run starts
    // Tools that break in the simulated world (`--break T1=0.62@4`): shorter from then on, cutting nothing.
    std::vector<machine::ToolBreak> toolBreaks;
    std::map<int, tools::LoadLimits> loadLimits; // per tool, over spindle-load.toml's (`--load-limits`)
    std::ostream* trace = nullptr;     // JSON Lines events
    // The most bytes the trace and the external output device's text keep (the first and the last
    // lines; see TraceWriter and ExternalDevices): an endless loop must not fill the disk or memory.
    std::uint64_t traceLimit = 256ull << 20;
    std::uint64_t externalOutputLimit = 64ull << 20;
    // A program file larger than this (mapped UTF-8) is kept in memory only in part: its chunks of
    // plain lines are parsed again when they run (gcode::BlockList), so a 1 GB program fits.
    std::uint64_t programKeptWholeUpTo = gcode::kProgramKeptWholeUpTo;
    // The machine's libraries are parsed once and joined to each program or MDI line while their
    // files read the same (LibraryCache); false parses them at every load (tests compare both).
    bool reuseParsedLibraries = true;
    // Told every machine event as it happens (the panel's simulation draws the path from them).
    machine::MachineObserver* observer = nullptr;
};

} // namespace m350::controller
