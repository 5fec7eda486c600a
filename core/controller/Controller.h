#pragma once

#include "core/config/HookFiles.h"
#include "core/params/IoPorts.h"
#include "core/config/MachineConfig.h"
#include "core/controller/BreakRun.h"
#include "core/controller/ExternalDevices.h"
#include "core/controller/HoldMotion.h"
#include "core/controller/Homing.h"
#include "core/controller/InterfaceSignalsPmc.h"
#include "core/controller/LibraryCache.h"
#include "core/controller/ManualControl.h"
#include "core/controller/MessageLog.h"
#include "core/controller/OperationControl.h"
#include "core/controller/OperatorPanel.h"
#include "core/controller/ParameterWrites.h"
#include "core/controller/PanelStatus.h"
#include "core/controller/ProgramStop.h"
#include "core/controller/RunEvents.h"
#include "core/controller/RunReport.h"
#include "core/controller/RunSettings.h"
#include "core/controller/RunState.h"
#include "core/controller/RunView.h"
#include "core/controller/StatusBoard.h"
#include "core/controller/MachineEventRouter.h"
#include "core/controller/MagazineDriver.h"
#include "core/controller/ToolBreakage.h"
#include "core/controller/SpindleToolByHand.h"
#include "core/controller/SpindleToolGuard.h"
#include "core/controller/ToolLifeCounter.h"
#include "core/controller/ToolTableEdits.h"
#include "core/controller/TraceWriter.h"
#include "core/gcode/Program.h"
#include "core/interp/ModalInterpreter.h"
#include "core/interp/WorkOffsets.h"
#include "core/machine/ScanMachine.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/Executor.h"
#include "core/macro/MachineAccess.h"
#include "core/macro/VariableStore.h"
#include "core/tools/ToolData.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m350::gcode {
class Parser;
struct SourceText;
} // namespace m350::gcode

namespace m350::controller {

// The one façade the CLI and the panel's session use: load a program with the machine's macro
// libraries, run it in virtual time, inspect the result. Owns the machine, the interpreter, the
// variables and the executor; implements the machine-side variables for the macro layer. Its
// parts, each a class with its own state: manual() (jog, handwheel, 试切 guide, overrides),
// homing() (回零), breakRun() (断点加工), operatorPanel() (dialogs, keys, watched inputs),
// toolTableEdits(), toolLife(), toolBreakage(), externalDevices() and status() (messages, trace,
// the run report); without an accessor: the machine's observer (MachineEventRouter), the checks
// of tool words and the spindle's tool (SpindleToolGuard), what a hold did to the machine
// (HoldMotion) and why the program holds the run (ProgramStop).
class Controller : public macro::MachineAccess,
                   private RunView,
                   private BreakRun::Starter {
public:
    Controller(config::MachineConfig config, RunSettings settings);
    ~Controller() override;

    // Parses the program and the machine's libraries. False when a syntax error prevents running;
    // diagnostics() then says why (and lists flow/lint findings in any case).
    bool loadFile(const std::string& path);
    bool loadMdi(const std::vector<std::string>& lines);
    const std::vector<gcode::Diagnostic>& diagnostics() const { return diagnostics_; }
    // The loaded program with the machine's libraries, as parsed (what check::StaticCheck reads).
    const gcode::Program& program() const { return program_; }
    // How many times the machine's libraries were parsed: once while their files stay as they are.
    std::uint64_t libraryParses() const { return libraries_.parses(); }

    // Hook files (Hooks.cpp; the table in config/HookFiles.h): the machine folder's programs that
    // the panel and the controller run when something happens. loadHook loads one as the program
    // to run, with the machine's libraries (its alarms name the hook's file:line:col), and sets
    // `variables` (#1504 for T.nc) after the run settings' ones; it runs like MDI lines: param 220
    // does not ask for homing first. False, with diagnostics, when the folder has no such file or
    // it does not parse. loadHookOrMdi is a panel key: its hook when the folder has one, else the
    // `fallback` MDI lines, the built-in behaviour.
    // The controller runs three itself: pause.nc when a run holds (PAUSE, M00, G04 P-1; START
    // first brings the axes back to where the hold stopped them), error.nc after an alarm (not
    // after 急停), each to its end at once beside the interrupted program; and ALL_T.nc as the
    // handler of M101. The built-in O501 (`M98 P501 X<axis>`) homes one axis natively.
    bool hasHook(config::Hook hook) const;
    bool loadHook(config::Hook hook, const std::map<int, double>& variables = {});
    bool loadHookOrMdi(config::Hook hook, const std::map<int, double>& variables,
                       const std::vector<std::string>& fallback);
    std::optional<config::Hook> loadedHook() const { return hook_; }
    // The operator at the panel (OperatorPanel.h): dialogs, the keys wired to inputs, K1-K7, the
    // external and FUNC keys, the sensor a macro waits on.
    OperatorPanel& operatorPanel() { return panel_; }
    const OperatorPanel& operatorPanel() const { return panel_; }

    // Runs the loaded program to its end (or an alarm) as fast as it can: start() + advance(inf).
    RunReport run();

    // The run as a panel drives it: cycle start, then advance() by the display's time steps; the
    // program executes the blocks whose time has come. hold() (暂停) decelerates and keeps the
    // program where it is (param 91: lift Z by param 70); resume() carries on from there; reset()
    // stops at once and rewinds; emergencyStop() (急停) stops at once with an alarm. Reset and E-stop
    // switch every output to its safe state.
    using RunState = controller::RunState;
    bool start();
    RunState advance(double seconds);
    void hold();
    void resume();
    void reset();
    void emergencyStop(const std::string& why = {});
    RunState runState() const override { return state_; }
    // Why the run holds when the program itself stopped (M00, M01 with the optional stop on, the
    // M350's G04 P-1): "M00 program stop (main.nc:12)"; empty for 暂停 or when running. resume()
    // is START. run() presses START by itself and notes it in the messages.
    const std::string& programStop() const { return programStop_.text(); }
    // Parameters 0-999 as they stand, for the panel's teach buttons (135-137) and IO page. A write
    // takes effect at once (setters, sensors, speeds); false for other numbers, a value that is
    // not finite or one that params::refusedParameterValue refuses.
    double parameter(int n) const;
    bool setParameter(int n, double value);
    // The user level at the panel (ParameterWrites.h): what the operator's MDI lines and programs
    // may write (#(N+500)) follows it; the machine's libraries and hook files write regardless.
    // Super until a panel says otherwise (m350-sim --level).
    void setUserLevel(params::UserLevel level) { writes_.setLevel(level); }
    params::UserLevel userLevel() const { return writes_.level(); }
    // Every parameter change since the last call, whoever made it, for the System Log.
    std::vector<ParameterWrites::Change> takeParameterChanges() { return writes_.take(config_.parameters); }
    // The panel's touch off or teach is about to write parameter `n` (so the log says who).
    void notePanelWrite(int n) { writes_.note(n, ParameterWrites::Writer::Panel); }
    // 断点加工 Break Run: start at a line, or again where a hold stopped (BreakRun.h).
    BreakRun& breakRun() { return breakRun_; }
    const BreakRun& breakRun() const { return breakRun_; }
    double displayTime() const override { return displayTime_; }
    machine::Axes displayPosition() const { return machine_.positionAt(displayTime_); }
    // What the panel shows now (PanelStatusView.cpp): positions at the display time, modes, IO.
    PanelStatus panelStatus();

    // 回零 homing and which axes are homed (Homing.h).
    Homing& homing() { return homing_; }
    const Homing& homing() const { return homing_; }
    // 清零: makes the current position the work zero of `axis` in the active system. For Z on the
    // M350 the stored offset excludes the tool's Z offset (params 930-945), so it holds the distance
    // between the setter and the workpiece and every set tool then cuts at the same Z.
    void zeroWorkAxis(int axis) { setWorkPosition(axis, 0.0); }
    // 坐标管理 / 分中: the current position gets work coordinate `value` on `axis` in the active
    // system (its offset moves; the others, G52, the common offset and the tool's stay).
    void setWorkPosition(int axis, double value);
    // The panel's edits of a variable (#50-#499, offsets #800-#844 ...), as a macro would write it.
    // False with a reason for a read-only or unknown variable, or a value that is not finite.
    bool setVariable(int number, double value, Message* why = nullptr);
    // The operator says which tool the spindle holds (after an E-stop in a change the macro may
    // have stopped before it recorded the tool): param 800 (#1300) on the M350, the PMC's spindle
    // tool (what M85 stores) on a FANUC. False while a program runs or holds, or below 0. It ends
    // the doubt a stop in a change leaves (toolDoubt()).
    bool setSpindleToolNumber(int tool);
    // Whether a stop in a tool change left the spindle's tool unknown (ToolDoubt.h): the next
    // change is refused at its T (M06 on a FANUC) until setSpindleToolNumber().
    const ToolDoubt& toolDoubt() const { return toolGuard_.doubt(); }

    // The panel's feed override (进给倍率) in percent, from 0 up to param 295 (150 % when it is 0);
    // G00 follows it when param 253 = 1. Returns the percentage set; while a FANUC macro's #3004
    // bit 1 is on, the machine runs at 100 % regardless.
    double setFeedOverride(double percent);
    // Single block (FANUC SBK): the run holds after each block that reaches the machine (not after
    // macro statements), unless #3003 bit 0 says otherwise; START goes on. RunSettings::singleBlock
    // sets it for a run (m350-sim --single-block).
    void setSingleBlock(bool on) { singleBlock_ = on; }
    bool singleBlock() const { return singleBlock_; }
    // FANUC #3003 / #3004 as the running macros set them (OperationControl.h).
    const OperationControl& operationControl() const { return operation_; }

    // The operator's manual control: jog keys, handwheel, 试切 guide, manual and spindle
    // overrides, spindle jog, the IO page's output switches (ManualControl.h).
    ManualControl& manual() { return manual_; }
    const ManualControl& manual() const { return manual_; }

    // Fault injection for training: input `pin` (1-24) stuck, delayed or bouncing from now on;
    // nullopt takes the fault off. `RunSettings::heldInputs` puts stuck faults on before a run.
    void setInputFault(int pin, std::optional<machine::InputFault> fault) { machine_.setInputFault(pin, fault); }
    // A trainer presses what is wired to input `pin` for a moment: it reads `level` for `seconds`.
    void pressInput(int pin, int level, double seconds) { machine_.pulseInput(pin, level, seconds); }

    // The tool table as the panel edits it (ToolTableEdits.h): rows, an import, touch off, whether
    // it changed since the last save (controller::saveToolTable in ToolTableSave.h saves it).
    ToolTableEdits& toolTableEdits() { return toolEdits_; }
    const ToolTableEdits& toolTableEdits() const { return toolEdits_; }

    // Reads any variable as a macro would, for --print and the panel.
    macro::Value variable(int number);
    const gcode::Dialect& dialect() const { return *config_.dialect; }
    // The external output device (POPEN, DPRNT, BPRNT, PCLOS) and the Modbus slaves (ExternalDevices.h).
    ExternalDevices& externalDevices() { return devices_; }
    const ExternalDevices& externalDevices() const { return devices_; }
    // What the controller says as a run goes (StatusBoard.h): the messages, the #1503 status line, the trace.
    StatusBoard& status() { return status_; }
    const StatusBoard& status() const { return status_; }
    // Every alarm and every run that reached its end, with its virtual time (RunEvents.h).
    const RunEvents& events() const { return events_; }
    // The machine's configuration as it stands: parameters, offsets of the folder, the tool table now.
    config::MachineConfig config() const;

    // What the machine view's scene reads (core/preview/MachineScene.cpp), without copies: the
    // folder's configuration as it stands (its parameters; the tool table as it stands is
    // toolData()'s), the tools' offsets, the magazine device and the offsets in force.
    const config::MachineConfig& machineConfig() const { return config_; }
    const tools::ToolData& toolData() const { return tools_; }
    const MagazineDriver& magazine() const { return magazine_; }
    const interp::ModalInterpreter& interpreter() const { return interp_; }

    // FANUC tool life management (ToolLifeCounter.h): the groups, the tool in use, the operator's reset.
    ToolLifeCounter& toolLife() { return toolLife_; }
    const ToolLifeCounter& toolLife() const { return toolLife_; }
    // Tool breakage (ToolBreakage.h): the spindle load as the PMC reads it, its monitor and history;
    // the tools as they really are (a break from RunSettings::toolBreaks shortens one at its time).
    const ToolBreakage& toolBreakage() const { return breakage_; }

    // macro::MachineAccess
    bool manageTools(macro::EvaluatedBlock& block) override;
    macro::Value readSystem(const macro::VariableInfo& info, int number) override;
    std::optional<Message> writeSystem(const macro::VariableInfo& info, int number, double value,
                                       std::string_view text) override;
    std::optional<HomingFailure> builtInHoming(int axis) override;
    std::optional<Message> parameterWrite(int parameter, double value) override;
    void homingStarts(int axis) override;

private:
    // A RESET, an E-stop or an alarm stops the run inside a tool change: the spindle's tool is in doubt.
    void noteStopInChange();
    bool load(const gcode::SourceText& source, gcode::FileRole role);
    void applyParameterOverrides(); // --param, before anything reads the parameters
    void applySettings();
    void configureMachine();
    void syncToolLength() { breakage_.syncToolLength(); }
    void setUpBreakageWatch();
    void enterSafeState();
    void stepOnce();
    int stepOnce(int toolBefore); // the spindle tool after the step
    // True once what started at machine time `since` (a run, a hook, homing) ran longer than
    // --max-sim-time (or the clock went nan); the move or dwell under way is then stopped where the
    // limit found it, so the report shows that moment. Each run gets the whole limit.
    bool passedTimeLimit(double since) final;
    // Stops the motion under way at virtual time t (SimulatedMachine::interrupt); the magazine
    // learns where a move it was told of really stopped.
    machine::SimulatedMachine::Remainder interruptMotion(double t, bool immediate);
    // "the program ran 3600 s of simulated time without ending (stopped at 7250.5 s)": what ran
    // over the limit, and the machine time it stopped at.
    std::vector<std::string> timeLimitNumbers(double since) const final;
    double runStartedAt() const final { return runStartedAt_; }
    void raiseAlarm(const Alarm& alarm) final;
    bool axisHomed(int axis) const final { return homing_.homed(axis); }
    void parseWithLibraries(gcode::Program& program, const gcode::SourceText& source, gcode::FileRole role,
                            std::vector<gcode::Diagnostic>& diagnostics) const;
    std::vector<LibraryCache::File> librariesFor(const std::string& mainPath) const;
    std::unique_ptr<macro::Executor> newExecutor();
    std::optional<Alarm> runEventHook(config::Hook hook);
    std::optional<Alarm> runHookProgramToEnd(const std::string& name);
    void runPauseHook();
    int spindleTool() const { return magazine_.spindleTool(); }
    void stopForOperator(const interp::ModalInterpreter::OperatorStop& stop);
    // After a step: the single block stop, and the PAUSE #3004 held back (RunControl.cpp).
    void stopAfterStep(std::uint64_t machineBlocksBefore);
    std::optional<Message> setOperationControl(int variable, double value);
    void resetOperationControl();
    void applyFeedOverride();
    bool optionalStopOn();
    OperatorPanel newOperatorPanel();

    config::MachineConfig config_;
    RunSettings settings_;
    interp::WorkOffsets offsets_;
    tools::ToolData tools_; // before interp_, which reads it
    machine::SimulatedMachine machine_;
    machine::ScanMachine scan_{machine_}; // what the interpreter drives: machine_, or a scan of it
    interp::ModalInterpreter interp_;
    macro::VariableStore store_;
    gcode::Program program_;
    mutable LibraryCache libraries_; // parseWithLibraries
    std::vector<gcode::Diagnostic> diagnostics_;
    std::unique_ptr<macro::Executor> executor_;
    double feedOverride_ = 100.0;
    double runStartedAt_ = 0.0;
    std::uint64_t runMovesFrom_ = 0; // the machine's movesMade() when the run started
    double timeLimitFrom_ = 0.0; // the run's start, moved on by its holds: --max-sim-time counts from here
    bool mdi_ = false;
    std::optional<config::Hook> hook_;  // the loaded program is this hook file
    bool inEventHook_ = false;          // pause.nc or error.nc runs: no hook starts inside it
    // The run state changes only through setState(); the parts read it by const reference.
    RunState state_ = RunState::Idle;
    void setState(RunState next);
    RunEvents events_;
    std::optional<Alarm> alarm_;
    double displayTime_ = 0.0;
    HoldMotion holdMotion_{machine_, config_.parameters}; // what a hold cut short, lifted, stopped
    ProgramStop programStop_;                        // see programStop()
    MachineEventRouter machineEvents_; // the machine's observer; before magazine_, which writes its input sources
    SpindleToolByHand handTool_{tools_, config_.randomToolChanger}; // the spindle's tool where no magazine device knows it
    MagazineDriver magazine_; // the magazine device and its wiring (none when the folder has none)
    SpindleToolGuard toolGuard_; // the T words, the doubt after a stop in a change, unset lengths; before status_
    StatusBoard status_;      // before devices_, which writes to its trace
    ExternalDevices devices_; // the external output device and the Modbus slaves
    ToolLifeCounter toolLife_;
    ToolBreakage breakage_;    // the tools as they really are, the spindle load
    ToolTableEdits toolEdits_; // the panel's edits of tools_
    OperatorPanel panel_;      // after what its parts read
    InterfaceSignalsPmc interfacePmc_; // a FANUC's #1000-#1015, #1032, #1100-#1133
    OperationControl operation_;       // #3003, #3004
    bool singleBlock_ = false;
    bool holdPending_ = false;         // PAUSE came while #3004 kept feed hold off

    // BreakRun::Starter (RunControl.cpp)
    macro::Executor* programExecutor() final { return executor_ && !mdi_ ? executor_.get() : nullptr; }
    void clearForStart() final;
    bool dialogPending() const final { return panel_.dialogPending(); }
    bool inToolChange() const final;
    Saved save() const final;
    void restore(const Saved& saved) final;
    void startClock(const std::string& where) final;
    void setRunState(RunState state) final { setState(state); }

    ManualControl manual_{machine_, config_.parameters, *this};
    Homing homing_{machine_, config_.parameters, config_.folder, *this};
    BreakRun breakRun_{program_, machine_, scan_, interp_, config_.parameters, manual_, homing_, *this};
    ParameterWrites writes_{config_.parameters};
};

} // namespace m350::controller
