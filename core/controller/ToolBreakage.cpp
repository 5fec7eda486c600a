#include "core/controller/ToolBreakage.h"

#include "core/controller/MagazineDriver.h"
#include "core/machine/SimulatedMachine.h"

namespace m350::controller {

ToolBreakage::ToolBreakage(machine::SimulatedMachine& machine, const MagazineDriver& magazine)
    : machine_(machine), magazine_(magazine) {}

void ToolBreakage::setUp(const config::MachineConfig& config, const RunSettings& settings) {
    world_ = machine::ToolWorld(config.toolLengths, config.toolDiameters);
    for (const machine::ToolBreak& broken : settings.toolBreaks) {
        world_.addBreak(broken);
    }
    tools::LoadMonitorSettings monitor = config.loadMonitor;
    for (const auto& [tool, limits] : settings.loadLimits) {
        monitor.tools[tool] = limits;
    }
    load_.monitor().setSettings(std::move(monitor));
    load_.setModel(config.spindleLoad);
}

void ToolBreakage::syncToolLength() {
    const int tool = magazine_.spindleTool();
    machine_.setToolLength(world_.length(tool, machine_.time()));
    machine_.setToolRadius(world_.diameter(tool).value_or(0.0) / 2.0);
}

std::optional<SpindleLoadWatch::Anomaly> ToolBreakage::sample(const machine::MachineEvent& event) {
    if (!world_.breaks().empty()) {
        syncToolLength();
    }
    return load_.sampleUpTo(machine_, event, world_, magazine_.spindleTool());
}

} // namespace m350::controller
