// What a break run (BreakRun) needs of the Controller to start the loaded program inside it.
#include "core/controller/Controller.h"

#include <algorithm>

namespace m350::controller {

void Controller::clearForStart() {
    alarm_.reset();
    panel_.clearDialog();
    panel_.clearSensorWait();
    programStop_.clear();
    resetOperationControl();
    devices_.beginRun(); // the scan opens it again where the program does (POPEN)
}

BreakRun::Starter::Saved Controller::save() const { return {offsets_, tools_.table(), config_.parameters}; }

void Controller::restore(const Saved& saved) {
    offsets_ = saved.offsets;
    tools_.replace(saved.tools);
    config_.parameters = saved.parameters;
    panel_.clearDialog();
    syncToolLength();
    setState(RunState::Idle);
}

void Controller::startClock(const std::string& where) {
    syncToolLength();
    displayTime_ = std::max(displayTime_, machine_.time());
    machine_.blockTime(displayTime_ - machine_.time());
    runStartedAt_ = displayTime_;
    timeLimitFrom_ = runStartedAt_;
    if (status_.trace()) {
        status_.trace()->runState(machine_.time(), "start at " + where);
    }
}

// Whether the scan is inside the T-code program on a machine whose magazine is a device.
bool Controller::inToolChange() const {
    if (!magazine_.device() || dialect().tCodeProgram < 0) {
        return false;
    }
    auto unit = program_.findUnit(dialect().tCodeProgram);
    auto where = executor_->location();
    if (!unit || !where || program_.units[*unit].begin >= program_.units[*unit].end) {
        return false;
    }
    const gcode::ProgramUnit& u = program_.units[*unit];
    const gcode::SourceLocation& first = program_.blocks[u.begin].location;
    const gcode::SourceLocation& last = program_.blocks[u.end - 1].location;
    return where->file == first.file && where->line >= first.line && where->line <= last.line;
}


} // namespace m350::controller
