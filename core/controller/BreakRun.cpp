// 断点加工 Break Run: the loaded program starts at a line of its main file, or again at the block a
// hold stopped, with the machine's state rebuilt by scanning the blocks before it (ScanMachine).
#include "core/controller/BreakRun.h"

#include "core/controller/ContinueRemainder.h"
#include "core/controller/Homing.h"
#include "core/controller/ManualControl.h"
#include "core/macro/Executor.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <array>
#include <limits>

namespace m350::controller {


namespace {

// A scan takes no time, so a macro waiting for an input would loop for ever: it stops here.
constexpr std::uint64_t kScanBlockLimit = 5'000'000;

bool refuse(Message* why, Message text) {
    if (why) {
        *why = std::move(text);
    }
    return false;
}

// What the scan rebuilt where the run starts, read as the scan ends.
struct Scanned {
    machine::Axes programAt;
    machine::SpindleState spindle;
    double rpm;
    bool coolant;
    std::array<std::optional<int>, machine::kOutputCount> outputs;
};

Scanned endScan(machine::ScanMachine& scan) {
    Scanned scanned{scan.position(), scan.spindleState(), scan.spindleRpm(), scan.coolantOn(), {}};
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        scanned.outputs[static_cast<std::size_t>(port - 1)] = scan.scannedOutput(port);
    }
    scan.endScan();
    return scanned;
}

} // namespace

BreakRun::BreakRun(const gcode::Program& program, machine::SimulatedMachine& machine, machine::ScanMachine& scan,
                   interp::ModalInterpreter& interp, const params::ParameterTable& parameters,
                   const ManualControl& manual, const Homing& homing, Starter& starter)
    : program_(program), machine_(machine), scan_(scan), interp_(interp), parameters_(parameters), manual_(manual),
      homing_(homing), starter_(starter) {}

std::string BreakRun::lineText(std::uint32_t block) const {
    const gcode::SourceLocation& where = program_.blocks[block].location;
    return program_.fileName(where) + ":" + std::to_string(where.line);
}

bool BreakRun::startAtLine(std::uint32_t line, Message* why) {
    auto unit = starter_.programExecutor() ? program_.mainUnit() : std::nullopt;
    if (!unit) {
        return refuse(why, message("start_no_program"));
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
        return refuse(why, message("start_line_not_in", {std::to_string(line), name, std::to_string(last)}));
    }
    if (std::uint32_t in = program_.unitOfBlock(*found); in != *unit) {
        return refuse(why, message("start_line_in_subprogram",
                                   {std::to_string(line), std::to_string(program_.units[in].number)}));
    }
    return startAt(*found, 0, false, why);
}

bool BreakRun::resumeAtPause(Message* why) {
    if (!paused_) {
        return refuse(why, message("start_no_pause"));
    }
    const PausePoint pause = *paused_;
    const bool fromStop = parameters_.get(param::kPauseResumeMode) != 0.0 && pause.mainMove;
    return startAt(pause.block, pause.pass, fromStop, why);
}

std::optional<BreakRun::BreakPoint> BreakRun::pauseBreakPoint() const {
    if (!paused_) {
        return std::nullopt;
    }
    const gcode::SourceLocation& where = program_.blocks[paused_->block].location;
    return BreakPoint{program_.files[where.file].path, where.line};
}

void BreakRun::rememberPause(const machine::SimulatedMachine::Remainder& rest) {
    const macro::Executor* executor = starter_.programExecutor();
    if (!executor || !executor->mainBlock()) {
        return;
    }
    using Kind = machine::SimulatedMachine::Remainder::Kind;
    PausePoint pause;
    pause.block = *executor->mainBlock();
    pause.pass = executor->mainBlocksStarted();
    pause.stoppedAt = machine_.position();
    pause.rest = rest;
    pause.mainMove = executor->callDepth() == 1 &&
                     (rest.kind == Kind::Rapid || rest.kind == Kind::Feed || rest.kind == Kind::Arc);
    pause.runFrom = runStartedFrom_;
    paused_ = pause;
}

// Starts at `block` of the main program (on its `pass`-th start; 0: the first time it comes).
// With `fromStopPoint` the block is scanned too and the machine finishes the move the hold cut.
bool BreakRun::startAt(std::uint32_t block, std::uint64_t pass, bool fromStopPoint, Message* why) {
    if (const RunState state = starter_.runState(); state == RunState::Running || state == RunState::Hold) {
        return refuse(why, message("start_running"));
    }
    if (manual_.jogging()) {
        return refuse(why, message("start_jogging"));
    }
    if (parameters_.get(param::kHomeBeforeProcessing) != 0.0 && !homing_.xyzHomed()) {
        return refuse(why, message("start_not_homed"));
    }
    // what a refusal puts back (variables stay as the scanned blocks set them)
    const interp::ModalState modal = interp_.state();
    const Starter::Saved saved = starter_.save();

    starter_.clearForStart();
    macro::Executor& executor = *starter_.programExecutor();
    executor.start(*program_.mainUnit());
    // a new start counts from where the machine stands; a resume from where the paused run began
    const machine::Axes from = pass == 0 || !paused_ ? machine_.position() : paused_->runFrom;
    std::optional<Message> problem = scanTo(executor, block, pass, fromStopPoint, from);
    if (!problem && interp_.state().group(7) != 40) {
        problem = message("start_compensation_on", {lineText(block)});
    }
    if (problem) {
        scan_.endScan();
        interp_.state() = modal;
        starter_.restore(saved);
        return refuse(why, *problem);
    }
    const Scanned scanned = endScan(scan_);
    starter_.startClock(lineText(block));
    runStartedFrom_ = from;
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        const auto& level = scanned.outputs[static_cast<std::size_t>(port - 1)];
        if (level && *level != machine_.output(port)) {
            machine_.setOutput(port, *level);
        }
    }
    if (scanned.coolant != machine_.coolantOn()) {
        machine_.coolant(scanned.coolant);
    }
    const std::optional<PausePoint> pause = paused_;
    approach(fromStopPoint ? pause->stoppedAt : scanned.programAt, scanned.spindle, scanned.rpm);
    if (fromStopPoint) {
        continueRemainder(machine_, pause->rest);
    }
    paused_.reset();
    starter_.setRunState(executor.state() == macro::Executor::State::Running ? RunState::Running : RunState::Finished);
    return true;
}

// Runs the main program's blocks as a scan until `block` is next (with `through`: until the main
// program is next after it). The scan stays on, so the caller can read what it rebuilt.
std::optional<Message> BreakRun::scanTo(macro::Executor& executor, std::uint32_t block, std::uint64_t pass,
                                            bool through, const machine::Axes& from) {
    scan_.beginScan(from);
    bool reached = false;
    for (std::uint64_t budget = kScanBlockLimit;; --budget) {
        if (executor.state() == macro::Executor::State::Alarmed) {
            const Alarm& alarm = *executor.alarm();
            const std::string said = alarm.messageId.empty()
                                         ? alarm.message
                                         : bilingual(alarm.message, messageText(alarm.messageId, alarm.messageArguments,
                                                                                MessageLanguage::Chinese));
            return message("scan_alarm", {lineText(block), alarm.file, std::to_string(alarm.line), said});
        }
        if (executor.state() != macro::Executor::State::Running) {
            return message("scan_never_reaches", {lineText(block)});
        }
        auto next = executor.nextMainBlock();
        bool at = next && *next == block && (pass == 0 || executor.mainBlocksStarted() + 1 == pass);
        if (reached ? next.has_value() : at) {
            if (reached || !through) {
                return std::nullopt;
            }
            reached = true;
        }
        if (budget == 0) {
            auto where = executor.location();
            return message("scan_no_end", {lineText(block), where ? program_.fileName(*where) + ":" + std::to_string(where->line)
                                                                  : std::string("?")});
        }
        executor.step();
        (void)interp_.takeStop(); // M00 and M01 before the line do not stop a scan
        if (scan_.refusal()) {
            return message("scan_refused", {bilingual(*scan_.refusal()), lineText(*executor.mainBlock())});
        }
        if (starter_.dialogPending()) {
            return message("scan_dialog", {lineText(*executor.mainBlock())});
        }
        if (starter_.inToolChange()) {
            return message("scan_tool_change", {lineText(*executor.mainBlock())});
        }
    }
}

// From where the machine stands to `target`: Z up to the higher of the two (and to param 69's safe
// height when param 90 asks for it), the spindle as the program has it, XY (A, B) over at rapid,
// then Z down at the program's feed.
void BreakRun::approach(const machine::Axes& target, machine::SpindleState spindle, double rpm) {
    const machine::Axes from = machine_.position();
    double safe = std::max(from(2), target(2));
    if (parameters_.get(param::kLiftBeforeStart) != 0.0) {
        safe = std::max(safe, parameters_.get(param::kSafeZ) + interp_.workOffset()(2));
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
        machine_.feed(target, feed > 0.0 ? feed : parameters_.get(param::kDefaultFeed));
    }
}

} // namespace m350::controller
