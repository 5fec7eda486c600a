// The operator's run controls: 暂停 hold and resume, reset, 急停 emergency stop, the feed override;
// and what a FANUC macro switches off of them (#3003, #3004: OperationControl), with the single
// block stop; and how a break run (BreakRun::Starter) starts the loaded program inside it.
#include "core/controller/Controller.h"

#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace m350::controller {


void Controller::hold() {
    if (state_ != RunState::Running) {
        return;
    }
    if (operation_.feedHoldSuppressed()) {
        // FANUC: the feed hold lamp lights, the run goes on and holds at the first block that
        // allows feed hold again
        if (!holdPending_) {
            holdPending_ = true;
            status_.postMessage(message("notice_pause_held_back", {std::to_string(static_cast<int>(operation_.value(4))),
                                                                   status_.source().file,
                                                                   std::to_string(status_.source().line)}));
        }
        return;
    }
    if (machine_.keepsHistory() && displayTime_ < machine_.moveStart()) {
        // the handwheel guide has the display behind the moves already issued (a retrace): their
        // blocks have run, so the run waits where the display is and goes on from there
        setState(RunState::Hold);
        if (status_.trace()) {
            status_.trace()->runState(displayTime_, "pause");
        }
        runPauseHook();
        return;
    }
    const machine::SimulatedMachine::Remainder rest = interruptMotion(displayTime_, false);
    toolLife_.manager().cutShortAt(machine_.time());
    breakRun_.rememberPause(rest);
    holdMotion_.held(rest);
    setState(RunState::Hold);
    if (status_.trace()) {
        status_.trace()->runState(displayTime_, "pause");
    }
    runPauseHook();
}

void Controller::resume() {
    if (state_ != RunState::Hold) {
        return;
    }
    if (machine_.time() < displayTime_) {
        timeLimitFrom_ += displayTime_ - machine_.time(); // a long hold is no runaway
        machine_.blockTime(displayTime_ - machine_.time()); // the clock ran while paused
    }
    if (status_.trace()) {
        status_.trace()->runState(machine_.time(), "resume");
    }
    const HoldMotion::Finished rest = holdMotion_.resume();
    if (rest.cut && !(executor_ && executor_->changingTool())) {
        toolLife_.manager().cut(rest.from, machine_.time()); // the rest of the cut the hold stopped
    }
    programStop_.clear();
    setState(RunState::Running);
}

void Controller::reset() {
    noteStopInChange();
    machine::SimulatedMachine::Remainder rest = interruptMotion(displayTime_, true);
    toolLife_.manager().cutShortAt(machine_.time());
    if (state_ == RunState::Running) {
        breakRun_.rememberPause(rest); // a run stopped by RESET resumes as a paused one does
    }
    if (std::isfinite(displayTime_) && machine_.time() < displayTime_) { // after run() the display is at infinity
        machine_.blockTime(displayTime_ - machine_.time());
    }
    enterSafeState();
    interp_.cancelRotation();
    holdMotion_.forget();
    alarm_.reset();
    programStop_.clear();
    panel_.clearSensorWait();
    panel_.clearDialog();
    resetOperationControl(); // FANUC clears #3003 and #3004 on reset
    setState(RunState::Idle); // start() runs the program again from its beginning
    if (status_.trace()) {
        status_.trace()->runState(displayTime_, "reset");
    }
}

double Controller::setFeedOverride(double percent) {
    double maximum = config_.parameters.get(param::kMaxFeedOverride);
    double applied = std::clamp(percent, 0.0, maximum > 0.0 ? maximum : 150.0);
    feedOverride_ = applied;
    applyFeedOverride();
    return applied;
}

// The panel's override, or 100 % while a macro's #3004 bit 1 is on.
void Controller::applyFeedOverride() {
    const double factor = operation_.overrideSuppressed() ? 1.0 : feedOverride_ / 100.0;
    machine_.setFeedOverride(factor, config_.parameters.get(param::kOverrideActsOnRapids) != 0.0);
}

std::optional<Message> Controller::setOperationControl(int variable, double value) {
    if (auto refused = operation_.set(variable, value)) {
        return refused;
    }
    applyFeedOverride();
    return std::nullopt;
}

void Controller::resetOperationControl() {
    operation_.reset();
    holdPending_ = false;
    applyFeedOverride();
}

// After a step of the run: with single block on, the run holds after a block that reached the
// machine (not after a macro statement), unless #3003 bit 0 suppresses it; a PAUSE #3004 held
// back takes effect after the block that allows feed hold again.
void Controller::stopAfterStep(std::uint64_t machineBlocksBefore) {
    if (state_ != RunState::Running || executor_->state() != macro::Executor::State::Running) {
        return;
    }
    const TraceSource where = status_.source();
    if (holdPending_ && !operation_.feedHoldSuppressed()) {
        holdPending_ = false;
        status_.postMessage(message("notice_pause_takes_effect", {where.file, std::to_string(where.line)}));
        hold();
        return;
    }
    if (singleBlock_ && executor_->machineBlocksExecuted() != machineBlocksBefore &&
        !operation_.singleBlockSuppressed()) {
        programStop_.singleBlock(where);
        setState(RunState::Hold);
        if (status_.trace()) {
            status_.trace()->programStop(machine_.time(), "single block stop", where);
        }
    }
}

void Controller::emergencyStop(const std::string& why) {
    noteStopInChange();
    interruptMotion(displayTime_, true);
    toolLife_.manager().cutShortAt(machine_.time());
    if (machine_.time() < displayTime_) {
        machine_.blockTime(displayTime_ - machine_.time());
    }
    holdMotion_.dropRemainder();
    raiseAlarm(Alarm::of(AlarmCode::EmergencyStop, why.empty() ? message("estop") : message("estop_extern", {why})));
    setState(RunState::EStop);
    if (status_.trace()) {
        status_.trace()->runState(displayTime_, "estop");
    }
}

machine::SimulatedMachine::Remainder Controller::interruptMotion(double t, bool immediate) {
    using Kind = machine::SimulatedMachine::Remainder::Kind;
    machine::SimulatedMachine::Remainder rest = machine_.interrupt(t, immediate);
    if (rest.kind == Kind::Rapid || rest.kind == Kind::Feed || rest.kind == Kind::Arc) {
        magazine_.moveStoppedAt(machine_.position());
    }
    return rest;
}

bool Controller::passedTimeLimit(double since) {
    if (machine_.time() - since <= settings_.maxSimTime) {
        return false; // a clock gone nan fails this test too
    }
    if (std::isfinite(machine_.time())) {
        interruptMotion(since + settings_.maxSimTime, true); // a move of years would report its end
    }
    return true;
}

std::vector<std::string> Controller::timeLimitNumbers(double since) const {
    auto said = [](double seconds) {
        std::ostringstream text;
        text << seconds;
        return text.str();
    };
    if (since == 0.0) {
        return {said(settings_.maxSimTime)};
    }
    return {said(settings_.maxSimTime), said(since), said(machine_.time())};
}

// BreakRun::Starter: what a break run needs of the Controller to start the loaded program inside it.

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
