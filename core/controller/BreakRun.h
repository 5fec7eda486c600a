#pragma once

#include "core/controller/RunState.h"
#include "core/gcode/Program.h"
#include "core/interp/ModalInterpreter.h"
#include "core/interp/WorkOffsets.h"
#include "core/machine/ScanMachine.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolData.h"

#include <cstdint>
#include <optional>
#include <string>

namespace m350::macro {
class Executor;
} // namespace m350::macro

namespace m350::controller {

class Homing;
class ManualControl;

// 断点加工 Break Run: the loaded program starts at a line of its main file, or again at the block a
// hold stopped, with the machine's state rebuilt by scanning the blocks before it (ScanMachine).
// Keeps where the last hold (or RESET mid-run) stopped the main file until the next start.
class BreakRun {
public:
    // What a break run needs of the Controller to start the loaded program inside it.
    class Starter {
    public:
        virtual RunState runState() const = 0;
        // The executor of the loaded program file; null without one, or for MDI lines.
        virtual macro::Executor* programExecutor() = 0;
        // Before the scan: no alarm, dialog, sensor wait or program stop stands; the external output
        // device is closed (the scan opens it again where the program does, POPEN).
        virtual void clearForStart() = 0;
        // Whether a scanned block asked the operator (#1505), or the scan is inside the T-code
        // program on a machine whose magazine is a device.
        virtual bool dialogPending() const = 0;
        virtual bool inToolChange() const = 0;
        // What a refused start puts back (variables stay as the scanned blocks set them).
        struct Saved {
            interp::WorkOffsets offsets;
            tools::ToolTable tools;
            params::ParameterTable parameters;
        };
        virtual Saved save() const = 0;
        virtual void restore(const Saved& saved) = 0; // and the run Idle
        // After the scan: the run's clock starts now; the trace says "start at `where`".
        virtual void startClock(const std::string& where) = 0;
        virtual void setRunState(RunState state) = 0;

    protected:
        ~Starter() = default;
    };

    BreakRun(const gcode::Program& program, machine::SimulatedMachine& machine, machine::ScanMachine& scan,
             interp::ModalInterpreter& interp, const params::ParameterTable& parameters, const ManualControl& manual,
             const Homing& homing, Starter& starter);

    // startAtLine starts the loaded program at `line` of the main file (the first block at or after
    // it, the first time the program reaches it): the blocks before it run as a scan (ScanMachine:
    // variables, IF/GOTO/WHILE, modal codes, F, S, spindle, coolant, outputs, tool; no motion, time
    // or events), then the machine goes from where it stands to where the program is (Z up to the
    // higher of the two, and param 90's safe Z; XY over; Z down at feed) and the run goes on.
    // Refused (false, `why`) while running or holding, for a line beyond the file or in a
    // subprogram, one the program never reaches, param 220 unhomed, G41/G42 active at the line, and
    // for what a scan cannot follow before it: a tool change with a magazine device, G31, a PMC M
    // code, a sensor wait, an operator dialog, an alarm. A refusal moves nothing; the modal state
    // and offsets are as before, variables as scanned.
    bool startAtLine(std::uint32_t line, Message* why);
    // After 暂停 and RESET (or RESET alone mid-run): starts again at the main file's block that ran
    // when paused (the same pass of a loop), rebuilt as above. Param 93 = 0 runs that block from its
    // start point; 1 from the point where the hold stopped it (a move of the main file; otherwise
    // from its start).
    bool resumeAtPause(Message* why);
    // Where the last 暂停 (or a RESET mid-run) stopped the main file, kept until the next start;
    // `file` is the main file's path.
    struct BreakPoint {
        std::string file;
        std::uint32_t line = 0;
    };
    std::optional<BreakPoint> pauseBreakPoint() const;

    // The Controller's run: it starts with the machine at `from` (G91 programs count from it); a
    // hold or RESET stopped it with `rest` of the motion under way not done; a start or a new
    // program forgets the pause.
    void runStartsFrom(const machine::Axes& from) { runStartedFrom_ = from; }
    void rememberPause(const machine::SimulatedMachine::Remainder& rest);
    void forgetPause() { paused_.reset(); }

private:
    // the main block a hold stopped, which pass over it, where it stopped
    struct PausePoint {
        std::uint32_t block = 0;
        std::uint64_t pass = 0;
        machine::Axes stoppedAt = machine::Axes::Zero();
        machine::SimulatedMachine::Remainder rest;
        bool mainMove = false; // the hold cut a move of that block itself, not of a call
        machine::Axes runFrom = machine::Axes::Zero(); // where the run began (G91 programs count from it)
    };

    bool startAt(std::uint32_t block, std::uint64_t pass, bool fromStopPoint, Message* why);
    std::optional<Message> scanTo(macro::Executor& executor, std::uint32_t block, std::uint64_t pass, bool through,
                                      const machine::Axes& from);
    std::string lineText(std::uint32_t block) const;
    void approach(const machine::Axes& target, machine::SpindleState spindle, double rpm);

    const gcode::Program& program_;
    machine::SimulatedMachine& machine_;
    machine::ScanMachine& scan_;
    interp::ModalInterpreter& interp_;
    const params::ParameterTable& parameters_;
    const ManualControl& manual_;
    const Homing& homing_;
    Starter& starter_;
    std::optional<PausePoint> paused_;
    machine::Axes runStartedFrom_ = machine::Axes::Zero();
};

} // namespace m350::controller
