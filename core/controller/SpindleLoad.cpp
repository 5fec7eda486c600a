// Tool breakage in the simulated world and the spindle load monitor (the FANUC article's second
// method): the load is sampled as virtual time passes and an anomaly stops the run like any alarm.
#include "core/controller/Controller.h"
#include "core/params/FanucParameters.h"

namespace m350::controller {

void Controller::setUpBreakageWatch() {
    world_ = machine::ToolWorld(config_.toolLengths, config_.toolDiameters);
    for (const machine::ToolBreak& broken : settings_.toolBreaks) {
        world_.addBreak(broken);
    }
    tools::LoadMonitorSettings monitor = config_.loadMonitor;
    for (const auto& [tool, limits] : settings_.loadLimits) {
        monitor.tools[tool] = limits;
    }
    loadWatch_.monitor().setSettings(std::move(monitor));
    if (config_.spindleLoad) {
        config_.spindleLoad->lambda = params::fanucParameter(config_.fanucParameters, params::kLoadMeterFullScale);
    }
    loadWatch_.setModel(config_.spindleLoad);
    if (config_.spindleLoad || !world_.breaks().empty()) {
        machine_.setObserver(this); // the load follows every move; a break changes the tool's length
    }
}

void Controller::watchSpindleLoad(const machine::MachineEvent& event) {
    if (!watchesSpindleLoad()) {
        return; // nothing to sample, nothing that breaks: the common case, every move of a program
    }
    if (!world_.breaks().empty()) {
        syncToolLength();
    }
    auto anomaly = loadWatch_.sampleUpTo(machine_, event, world_, spindleTool());
    if (anomaly && state_ == RunState::Running && executor_) {
        interruptMotion(anomaly->time, false); // the axes brake from where they were then
        throw macro::MacroError{AlarmCode::SpindleLoad, anomaly->message, 0};
    }
}

} // namespace m350::controller
