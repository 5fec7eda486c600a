#include "core/controller/ToolBreakage.h"

#include "core/controller/MagazineDriver.h"
#include "core/machine/SimulatedMachine.h"
#include "core/tools/ToolData.h"

#include <algorithm>

namespace m350::controller {

ToolBreakage::ToolBreakage(machine::SimulatedMachine& machine, const MagazineDriver& magazine)
    : machine_(machine), magazine_(magazine) {}

void ToolBreakage::setUp(const config::MachineConfig& config, const RunSettings& settings) {
    world_ = machine::ToolWorld(config.toolLengths, config.toolDiameters);
    if (config.dialect->id == gcode::DialectId::M350) {
        // A tool machine.toml does not list (a virtual tool, params 973-992) is as long as its stored
        // Z offset says (the machine Z it trips the fixed setter at, less the setter's top): setting
        // it again finds what was stored instead of a zero length. One never set is 0 long.
        const params::ParameterTable& parameters = config.parameters; // the Controller's: it follows every edit
        const double top = config.setterTop;
        world_.setUnlisted([&parameters, top](int tool) {
            const std::optional<int> offset = tools::m350ZParameter(tool, parameters);
            const double stored = offset ? parameters.get(*offset) : 0.0;
            return stored != 0.0 ? std::max(0.0, stored - top) : 0.0;
        });
    }
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
