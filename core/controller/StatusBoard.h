#pragma once

#include "core/common/Alarm.h"
#include "core/config/MachineConfig.h"
#include "core/controller/MessageLog.h"
#include "core/controller/RunReport.h"
#include "core/controller/RunSettings.h"
#include "core/controller/RunState.h"
#include "core/controller/ToolDoubt.h"
#include "core/controller/TraceWriter.h"
#include "core/gcode/Diagnostic.h"
#include "core/machine/MachineTypes.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m350::gcode {
class Program;
}

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::macro {
class Executor;
}

namespace m350::interp {
class ModalInterpreter;
}

namespace m350::controller {

class MagazineDriver;

// What the controller says as a run goes: the messages of a run (#3006 texts, dialogs, what run()
// did for the absent operator; MessageLog), the status line's #1503 text, and the JSON Lines trace
// (RunSettings::trace; TraceWriter), each event with the program line it came from; and how the
// panel prints the modes and the spindle; what a run leaves behind (RunReport).
class StatusBoard {
public:
    // What the board reads; all of it belongs to the Controller and outlives it.
    struct Context {
        const config::MachineConfig& config;
        const machine::SimulatedMachine& machine;
        const interp::ModalInterpreter& interp;
        const MagazineDriver& magazine;
        const std::unique_ptr<macro::Executor>& executor; // made anew for each program
        const gcode::Program& program;
        const std::vector<gcode::Diagnostic>& diagnostics;
        const RunState& state;
        const std::optional<Alarm>& alarm;
        const ToolDoubt& toolDoubt;
    };
    // `settings`: where the trace goes (RunSettings::trace) and how much of it is kept.
    StatusBoard(Context context, const RunSettings& settings);

    // The block executing now (file, line); empty before a program has run.
    TraceSource source() const;
    // The same as the parsed program's file index, line and column: no string made (a preview asks
    // it for every move).
    std::optional<gcode::SourceLocation> location() const;
    // A message for the log (clipped like an echo), in the trace too.
    void postMessage(std::string text);
    void postMessage(const Message& words);
    // An alarm's words as a line of the messages (by its id when it has one).
    void postMessage(const Alarm& notice);
    const MessageLog& messages() const { return messages_; }
    // #1503: the status line's text, until #1503 = 1000 clears it.
    void showStatus(std::string text) {
        statusLine_ = std::move(text);
        notice_.reset();
    }
    void clearStatus() {
        statusLine_.clear();
        notice_.reset();
    }
    const std::string& statusLine() const { return statusLine_; }
    // A warning the controller itself gives (a tool without a length): a message, the report's
    // warnings, and the status line's text until #1503 writes it; it carries its message id
    // (Alarm::messageId) so that the panel says it in its language.
    void warn(const Alarm& warning);
    const std::optional<Alarm>& notice() const { return notice_; }

    // The run as `m350-sim` reports it: status, alarm, diagnostics, positions, tool, pockets,
    // outputs, messages, time and blocks.
    RunReport report() const;
    // The active modal codes as the Monitor page prints them: "G00 G17 G90 G94 G21 G40 G49 G80 G54 F3000 S0".
    std::string modalLine() const;
    // The spindle as the panel shows it: STOP FWD REV ORIENT, JOG while the spindle jog key turns
    // it, TAP while a tapping cycle (G84/G74) is active and it turns.
    machine::SpindleState spindleDisplay() const;

    // The trace, nullptr when the run writes none.
    TraceWriter* trace() const { return trace_.get(); }
    const std::unique_ptr<TraceWriter>& traceWriter() const { return trace_; }
    // Writes the end of a trace that reached its limit (RunSettings::traceLimit): call once the run
    // is over, before the trace file is closed.
    void finishTrace() {
        if (trace_) trace_->finish();
    }

private:
    Context context_;
    MessageLog messages_;
    std::string statusLine_;
    std::optional<Alarm> notice_;  // the last warning, while the status line shows it
    std::vector<Alarm> warnings_;  // every warning, for the report
    std::unique_ptr<TraceWriter> trace_;
    using ModalLineKey = std::array<double, 12>; // the groups shown, the work system, G68, F, S
    mutable ModalLineKey modalKey_{};
    mutable std::string modalLine_; // what modalLine gave for modalKey_
};

} // namespace m350::controller
