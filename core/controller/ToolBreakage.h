#pragma once

#include "core/config/MachineConfig.h"
#include "core/controller/RunSettings.h"
#include "core/controller/SpindleLoadWatch.h"
#include "core/machine/ToolWorld.h"

#include <optional>

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::controller {

class MagazineDriver;

// Tool breakage (the FANUC article's second method): the tools as they really are in the simulated
// world (a break from RunSettings::toolBreaks shortens one at its time) and the spindle load the
// PMC reads, sampled as virtual time passes. The tool in the spindle decides where the setter trips.
// What an anomaly stops is the controller's: sample() only says that one came.
class ToolBreakage {
public:
    ToolBreakage(machine::SimulatedMachine& machine, const MagazineDriver& magazine);

    // The machine folder's tool sizes, load model and monitor settings, with the run's breaks and
    // per-tool limits over them (after the parameter overrides: the model's lambda is param 4127).
    void setUp(const config::MachineConfig& config, const RunSettings& settings);
    // Whether there is anything to follow: a load model to sample or a tool that breaks. Not so on
    // most machines, where every move of a program passes without a look.
    bool active() const { return load_.model() || !world_.breaks().empty(); }
    // The tool in the spindle decides where the setter trips: the simulated world's tool length (as
    // it is now: a broken tool is shorter) and radius.
    void syncToolLength();
    // Follows one machine event: the broken tool's length, the load samples due; the first anomaly.
    std::optional<SpindleLoadWatch::Anomaly> sample(const machine::MachineEvent& event);
    // A new program starts a new monitor history.
    void restartMonitor() { load_.monitor().restart(); }
    void startAt(double t) { load_.startAt(t); }

    // The spindle load as the PMC reads it, its monitor and history.
    const SpindleLoadWatch& spindleLoad() const { return load_; }
    // The tools as they really are.
    const machine::ToolWorld& world() const { return world_; }

private:
    machine::SimulatedMachine& machine_;
    const MagazineDriver& magazine_;
    machine::ToolWorld world_;
    SpindleLoadWatch load_;
};

} // namespace m350::controller
