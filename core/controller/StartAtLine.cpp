// 断点加工 Break Run: the loaded program starts at a line of its main file, or again at the block a
// hold stopped, with the machine's state rebuilt by scanning the blocks before it (ScanMachine).
#include "core/controller/Controller.h"

#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <limits>

namespace m350::controller {


namespace {

// A scan takes no time, so a macro waiting for an input would loop for ever: it stops here.
constexpr std::uint64_t kScanBlockLimit = 5'000'000;

bool refuse(std::string* why, std::string text) {
    if (why) {
        *why = std::move(text);
    }
    return false;
}

} // namespace

std::string Controller::lineText(std::uint32_t block) const {
    const gcode::SourceLocation& where = program_.blocks[block].location;
    return program_.fileName(where) + ":" + std::to_string(where.line);
}

bool Controller::startAtLine(std::uint32_t line, std::string* why) {
    auto unit = executor_ && !mdi_ ? program_.mainUnit() : std::nullopt;
    if (!unit) {
        return refuse(why, "no program file is loaded");
    }
    // The file's blocks are consecutive and in line order (it is parsed in one go): a binary search
    // finds the line without reading every block (a 1 GB program keeps most of them on disk).
    const std::uint32_t file = program_.units[*unit].file;
    std::uint32_t begin = program_.units[*unit].begin;
    std::uint32_t end = begin;
    for (const gcode::ProgramUnit& u : program_.units) {
        if (u.file == file) {
            begin = std::min(begin, u.begin);
            end = std::max(end, u.end);
        }
    }
    const std::uint32_t last = end > begin ? program_.blocks[end - 1].location.line : 0;
    std::optional<std::uint32_t> found;
    std::uint32_t low = begin;
    std::uint32_t high = end;
    while (low < high) {
        const std::uint32_t middle = low + (high - low) / 2;
        if (program_.blocks[middle].location.line < line) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    if (low < end) {
        found = low;
    }
    const std::string name = program_.files[file].name;
    if (line == 0 || !found) {
        return refuse(why, "line " + std::to_string(line) + " is not in " + name + " (its blocks are on lines 1-" +
                               std::to_string(last) + ")");
    }
    if (std::uint32_t in = program_.unitOfBlock(*found); in != *unit) {
        return refuse(why, "line " + std::to_string(line) + " is in O" + std::to_string(program_.units[in].number) +
                               ", a subprogram: start at the line of the main program that calls it");
    }
    return startAt(*found, 0, false, why);
}

bool Controller::resumeAtPause(std::string* why) {
    if (!paused_) {
        return refuse(why, "no paused run to resume (PAUSE, then RESET)");
    }
    const PausePoint pause = *paused_;
    const bool fromStop = config_.parameters.get(param::kPauseResumeMode) != 0.0 && pause.mainMove;
    return startAt(pause.block, pause.pass, fromStop, why);
}

std::optional<Controller::BreakPoint> Controller::pauseBreakPoint() const {
    if (!paused_) {
        return std::nullopt;
    }
    const gcode::SourceLocation& where = program_.blocks[paused_->block].location;
    return BreakPoint{program_.files[where.file].path, where.line};
}

void Controller::rememberPause(const machine::SimulatedMachine::Remainder& rest) {
    if (!executor_ || mdi_ || !executor_->mainBlock()) {
        return;
    }
    using Kind = machine::SimulatedMachine::Remainder::Kind;
    PausePoint pause;
    pause.block = *executor_->mainBlock();
    pause.pass = executor_->mainBlocksStarted();
    pause.stoppedAt = machine_.position();
    pause.rest = rest;
    pause.mainMove = executor_->callDepth() == 1 &&
                     (rest.kind == Kind::Rapid || rest.kind == Kind::Feed || rest.kind == Kind::Arc);
    pause.runFrom = runStartedFrom_;
    paused_ = pause;
}

// Starts at `block` of the main program (on its `pass`-th start; 0: the first time it comes).
// With `fromStopPoint` the block is scanned too and the machine finishes the move the hold cut.
bool Controller::startAt(std::uint32_t block, std::uint64_t pass, bool fromStopPoint, std::string* why) {
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        return refuse(why, "the program is running: RESET first");
    }
    if (jogging()) {
        return refuse(why, "a manual move is under way");
    }
    if (config_.parameters.get(param::kHomeBeforeProcessing) != 0.0 && !(homed(0) && homed(1) && homed(2))) {
        return refuse(why, "机械未归零不能自动加工! (home X, Y and Z first: parameter 220)");
    }
    // what a refusal puts back (variables stay as the scanned blocks set them)
    const interp::ModalState modal = interp_.state();
    const interp::WorkOffsets offsets = offsets_;
    const tools::ToolTable tools = tools_.table();
    const params::ParameterTable parameters = config_.parameters;

    alarm_.reset();
    pendingDialog_.reset();
    sensorWatch_.clear();
    programStop_.clear();
    devices_.closeOutputDevice(); // the scan opens it again where the program does (POPEN)
    executor_->start(*program_.mainUnit());
    // a new start counts from where the machine stands; a resume from where the paused run began
    const machine::Axes from = pass == 0 || !paused_ ? machine_.position() : paused_->runFrom;
    std::optional<std::string> problem = scanTo(block, pass, fromStopPoint, from);
    if (!problem && interp_.state().group(7) != 40) {
        problem = "cutter compensation (G41/G42) is on at " + lineText(block) + ": start before the G41 or after the G40";
    }
    if (problem) {
        scan_.endScan();
        interp_.state() = modal;
        offsets_ = offsets;
        tools_.replace(tools);
        config_.parameters = parameters;
        pendingDialog_.reset();
        syncToolLength();
        state_ = RunState::Idle;
        return refuse(why, *problem);
    }
    const machine::Axes programAt = scan_.position();
    const machine::SpindleState spindle = scan_.spindleState();
    const double rpm = scan_.spindleRpm();
    const bool coolant = scan_.coolantOn();
    std::array<std::optional<int>, machine::kOutputCount> outputs;
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        outputs[static_cast<std::size_t>(port - 1)] = scan_.scannedOutput(port);
    }
    scan_.endScan();
    syncToolLength();

    displayTime_ = std::max(displayTime_, machine_.time());
    machine_.blockTime(displayTime_ - machine_.time());
    runStartedAt_ = displayTime_;
    timeLimitFrom_ = runStartedAt_;
    runStartedFrom_ = from;
    if (status_.trace()) {
        status_.trace()->runState(machine_.time(), "start at " + lineText(block));
    }
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        const auto& level = outputs[static_cast<std::size_t>(port - 1)];
        if (level && *level != machine_.output(port)) {
            machine_.setOutput(port, *level);
        }
    }
    if (coolant != machine_.coolantOn()) {
        machine_.coolant(coolant);
    }
    const std::optional<PausePoint> pause = paused_;
    approach(fromStopPoint ? pause->stoppedAt : programAt, spindle, rpm);
    if (fromStopPoint) {
        continueRemainder(pause->rest);
    }
    paused_.reset();
    state_ = executor_->state() == macro::Executor::State::Running ? RunState::Running : RunState::Finished;
    return true;
}

// Runs the main program's blocks as a scan until `block` is next (with `through`: until the main
// program is next after it). The scan stays on, so the caller can read what it rebuilt.
std::optional<std::string> Controller::scanTo(std::uint32_t block, std::uint64_t pass, bool through,
                                              const machine::Axes& from) {
    scan_.beginScan(from);
    bool reached = false;
    for (std::uint64_t budget = kScanBlockLimit;; --budget) {
        if (executor_->state() == macro::Executor::State::Alarmed) {
            const Alarm& alarm = *executor_->alarm();
            return "the blocks before " + lineText(block) + " raise an alarm at " + alarm.file + ":" +
                   std::to_string(alarm.line) + ": " + alarm.message;
        }
        if (executor_->state() != macro::Executor::State::Running) {
            return "the program never reaches " + lineText(block) + " (it ends, or jumps over it, first)";
        }
        auto next = executor_->nextMainBlock();
        bool at = next && *next == block && (pass == 0 || executor_->mainBlocksStarted() + 1 == pass);
        if (reached ? next.has_value() : at) {
            if (reached || !through) {
                return std::nullopt;
            }
            reached = true;
        }
        if (budget == 0) {
            auto where = executor_->location();
            return "the blocks before " + lineText(block) + " do not end in a scan (a wait for an input at " +
                   (where ? program_.fileName(*where) + ":" + std::to_string(where->line) : std::string("?")) + "?)";
        }
        executor_->step();
        (void)interp_.takeStop(); // M00 and M01 before the line do not stop a scan
        if (scan_.refusal()) {
            return *scan_.refusal() + " at " + lineText(*executor_->mainBlock()) + ", before the start line: a scan cannot";
        }
        if (pendingDialog_) {
            return lineText(*executor_->mainBlock()) + " asks the operator (#1505) before the start line";
        }
        if (inToolChange()) {
            return lineText(*executor_->mainBlock()) +
                   " changes the tool: the magazine's tool accounting cannot be scanned (change the tool, then start "
                   "after that line)";
        }
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

// From where the machine stands to `target`: Z up to the higher of the two (and to param 69's safe
// height when param 90 asks for it), the spindle as the program has it, XY (A, B) over at rapid,
// then Z down at the program's feed.
void Controller::approach(const machine::Axes& target, machine::SpindleState spindle, double rpm) {
    const machine::Axes from = machine_.position();
    double safe = std::max(from(2), target(2));
    if (config_.parameters.get(param::kLiftBeforeStart) != 0.0) {
        safe = std::max(safe, config_.parameters.get(param::kSafeZ) + interp_.workOffset()(2));
    }
    if (from(2) < safe) {
        machine::Axes up = from;
        up(2) = safe;
        machine_.rapid(up);
    }
    if (spindle != machine_.spindleState() || rpm != machine_.spindleRpm()) {
        machine_.spindle(spindle, rpm);
    }
    machine::Axes over = target;
    over(2) = safe;
    if ((over - machine_.position()).norm() > 1e-9) {
        machine_.rapid(over);
    }
    if (target(2) < safe) {
        double feed = interp_.state().feed;
        if (interp_.state().group(5) == 95) {
            feed *= interp_.state().spindleSpeed;
        }
        machine_.feed(target, feed > 0.0 ? feed : config_.parameters.get(param::kDefaultFeed));
    }
}

} // namespace m350::controller
