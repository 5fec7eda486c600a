#pragma once

#include "core/files/AtomicFile.h"
#include "core/config/HookFiles.h"
#include "core/params/IoPorts.h"
#include "core/config/MachineConfig.h"
#include "core/controller/ExternalDevices.h"
#include "core/controller/KeyPress.h"
#include "core/controller/ManualMotionState.h"
#include "core/controller/MessageLog.h"
#include "core/controller/PanelStatus.h"
#include "core/controller/RunReport.h"
#include "core/controller/RunSettings.h"
#include "core/controller/RunState.h"
#include "core/controller/SensorWatch.h"
#include "core/controller/StatusBoard.h"
#include "core/controller/MagazineDriver.h"
#include "core/controller/ToolBreakage.h"
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
// variables and the executor; implements the machine-side variables for the macro layer.
class Controller : public macro::MachineAccess, public machine::MachineObserver {
public:
    Controller(config::MachineConfig config, RunSettings settings);
    ~Controller() override;

    // Parses the program and the machine's libraries. False when a syntax error prevents running;
    // diagnostics() then says why (and lists flow/lint findings in any case).
    bool loadFile(const std::string& path);
    bool loadMdi(const std::vector<std::string>& lines);
    const std::vector<gcode::Diagnostic>& diagnostics() const { return diagnostics_; }

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
    // The panel's K1-K7 (params 210-216) and the external keys 1-6 (params 272-277) (UserKeys.cpp):
    // 0 loads key-N.nc / extnc<N-1>-1.nc (start() then runs it), 1-21 switches that output over,
    // above 1000 is the code of the panel key it stands for, which the panel presses.
    using KeyPress = controller::KeyPress;
    KeyPress pressUserKey(int key);
    KeyPress pressExternKey(int key);
    // FUNC K01-K14: #1996 = 249 + key, then ext_button.nc (`M#1996`), or that M code as MDI.
    bool loadFunctionKey(int key);

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
    RunState runState() const { return state_; }
    // Why the run holds when the program itself stopped (M00, M01 with the optional stop on, the
    // M350's G04 P-1): "M00 program stop (main.nc:12)"; empty for 暂停 or when running. resume()
    // is START. run() presses START by itself and notes it in the messages.
    const std::string& programStop() const { return programStop_; }
    // A macro waiting for a sensor (SensorWatch.h); the wait ends in an alarm after
    // RunSettings::sensorTimeout.
    using SensorWait = controller::SensorWait;
    std::optional<SensorWait> sensorWait() const;
    // An operator dialog (#1505 = kind(text)) the run waits on: with RunSettings::operatorPresent
    // the run holds after the block that wrote #1505 until answerDialog(); #1505 then reads 1 for
    // Enter and 0 for Esc. `#1505 = -5000(text)` only shows the text. Without an operator (and in
    // run()) every dialog is answered with Enter at once and the messages say so.
    struct Dialog {
        std::string text;
        int kind;
    };
    std::optional<Dialog> pendingDialog() const { return pendingDialog_; }
    void answerDialog(bool enter);
    // The operator presses the extern START key (param 599's input) for a moment, as the
    // virtual-tool prompt asks; nothing when the key is not wired.
    void pressExternStart();
    // The operator's keys wired to inputs (OperatorInputs.cpp), read at every advance(): the extern
    // E-stop (param 605) stops the machine while its input is active (RESET does not clear it while
    // the key is held); a press of the extern START (599), PAUSE (602) or an external key 1-6
    // (581-596) is queued for the panel, which acts on it as on its own key. START is no key press
    // while a program runs: macros read it (the virtual-tool prompt). At most kOperatorKeyQueue
    // presses wait; older ones are dropped.
    struct OperatorKey {
        enum class Kind { Start, Pause, ExternKey } kind;
        int key = 0; // ExternKey: 1-6
        bool operator==(const OperatorKey&) const = default;
    };
    static constexpr std::size_t kOperatorKeyQueue = 16;
    std::vector<OperatorKey> takeOperatorKeys();
    // Parameters 0-999 as they stand, for the panel's teach buttons (135-137) and IO page. A write
    // takes effect at once (setters, sensors, speeds); false for other numbers, a value that is
    // not finite or one that params::refusedParameterValue refuses.
    double parameter(int n) const;
    // What the loaded program (its main or MDI file) would alarm on that is knowable without
    // running it: a word twice in a block, an unknown G code, a variable that does not exist or is
    // read-only, 1/0 in constants, an O program calling itself unconditionally (StaticCheck.cpp).
    std::vector<gcode::Diagnostic> checkWithoutRunning();
    bool setParameter(int n, double value);
    // 断点加工 Break Run (StartAtLine.cpp). startAtLine starts the loaded program at `line` of the
    // main file (the first block at or after it, the first time the program reaches it): the
    // blocks before it run as a scan (ScanMachine: variables, IF/GOTO/WHILE, modal codes, F, S,
    // spindle, coolant, outputs, tool; no motion, time or events), then the machine goes from where
    // it stands to where the program is (Z up to the higher of the two, and param 90's safe Z; XY
    // over; Z down at feed) and the run goes on. Refused (false, `why`) while running or holding,
    // for a line beyond the file or in a subprogram, one the program never reaches, param 220
    // unhomed, G41/G42 active at the line, and for what a scan cannot follow before it: a tool
    // change with a magazine device, G31, a PMC M code, a sensor wait, an operator dialog, an alarm.
    // A refusal moves nothing; the modal state and offsets are as before, variables as scanned.
    bool startAtLine(std::uint32_t line, std::string* why);
    // After 暂停 and RESET (or RESET alone mid-run): starts again at the main file's block that ran when paused (the same
    // pass of a loop), rebuilt as above. Param 93 = 0 runs that block from its start point; 1 from
    // the point where the hold stopped it (a move of the main file; otherwise from its start).
    bool resumeAtPause(std::string* why);
    // Where the last 暂停 (or a RESET mid-run) stopped the main file, kept until the next start;
    // `file` is the main file's path.
    struct BreakPoint {
        std::string file;
        std::uint32_t line = 0;
    };
    std::optional<BreakPoint> pauseBreakPoint() const;
    double displayTime() const { return displayTime_; }
    machine::Axes displayPosition() const { return machine_.positionAt(displayTime_); }
    // What the panel shows now (PanelStatusView.cpp): positions at the display time, modes, IO.
    PanelStatus panelStatus();

    // 回零: homes the given axes (0 X .. 4 B), Z first. An alarm when an axis has no home switch.
    std::optional<Alarm> home(const std::vector<int>& axes);
    bool homed(int axis) const { return homed_[static_cast<std::size_t>(axis)] != 0; }
    // Param 127 = 0 asks at boot whether to home (是否进行开机寻零操作?) while X, Y, Z are not homed.
    bool needsBootHomingPrompt() const;
    // 清零: makes the current position the work zero of `axis` in the active system. For Z on the
    // M350 the stored offset excludes the tool's Z offset (params 930-945), so it holds the distance
    // between the setter and the workpiece and every set tool then cuts at the same Z.
    void zeroWorkAxis(int axis) { setWorkPosition(axis, 0.0); }
    // 坐标管理 / 分中: the current position gets work coordinate `value` on `axis` in the active
    // system (its offset moves; the others, G52, the common offset and the tool's stay).
    void setWorkPosition(int axis, double value);
    // The panel's edits of a variable (#50-#499, offsets #800-#844 ...), as a macro would write it.
    // False with a reason for a read-only or unknown variable, or a value that is not finite.
    bool setVariable(int number, double value, std::string* why = nullptr);
    // The operator says which tool the spindle holds (after an E-stop in a change the macro may
    // have stopped before it recorded the tool): param 800 (#1300) on the M350, the PMC's spindle
    // tool (what M85 stores) on a FANUC. False while a program runs or holds, or below 0.
    bool setSpindleToolNumber(int tool);

    // The panel's feed override (进给倍率) in percent, from 0 up to param 295 (150 % when it is 0);
    // G00 follows it when param 253 = 1. Returns the percentage in effect.
    double setFeedOverride(double percent);

    // The panel's spindle jog key (主轴点动): turns the spindle at param 85's speed, or stops it.
    // Refused (false) while a program runs.
    bool spindleJog(bool on);

    // Manual motion (ManualMotion.cpp). Axis 0..4 = X Y Z A B. Moves start at the display time (or
    // after a manual move still under way) and advance() shows them; soft limits (param 155) bound
    // every one. Refused (false) while a program runs or holds, in alarm or E-stop.
    using JogMode = controller::JogMode;
    void setJogMode(JogMode mode); // a held CONT key is released
    JogMode jogMode() const { return manual_.mode; }
    void setJogStep(double distance); // mm (deg) per STEP press; ignored unless positive
    double jogStep() const { return manual_.step; }
    void setJogHighSpeed(bool high); // 高速 params 40-44 / 低速 45-49, capped by 35-39
    // 手动倍率 SJR: 0 up to param 295 (150 % when it is 0); returns what applies.
    double setJogOverride(double percent);
    // CONT: moves until jogRelease() (to the soft limit, or kJogTravel); STEP: one jogStep();
    // MPG: nothing (false). direction +1 / -1.
    bool jogPress(int axis, int direction);
    // Key up: a CONT move brakes to rest at the manual stop acceleration (params 55-59).
    void jogRelease(int axis);
    // The handwheel: `detents` (signed) turned over the next `seconds` at x1, x10 or x100. With
    // the guide on and a program running it drives the guide (HandwheelGuide.cpp); in MPG mode
    // with no program running it moves the axis detents * multiplier * param 172 (param 175
    // reverses) at up to the speed of params 176-178, no faster than the wheel turns, ramping at
    // params 181-185. Otherwise false.
    bool wheelTurn(int axis, int multiplier, int detents, double seconds);
    static constexpr double kJogTravel = 10000.0; // mm a CONT jog runs without soft limits

    // 试切 handwheel guide (HandwheelGuide.cpp): while on and a program runs, the program's time
    // advances only as the wheel turns (see GuideOverride). Turning backwards holds or retraces the
    // path already made (the last SimulatedMachine::kHistoryMoves moves); turning forward again
    // replays it, then new blocks execute. A retrace undoes motion only: outputs, spindle and
    // variables stay as the blocks set them. Off: the run goes on at normal speed.
    using GuideReverse = controller::GuideReverse;
    void setHandwheelGuide(bool on);
    bool handwheelGuide() const { return manual_.guide; }
    void setGuideReverse(GuideReverse mode) { manual_.reverse = mode; }

    // 主轴倍率 SRO, 50-150 % (clamped): the spindle speed shown follows it. Returns what applies.
    double setSpindleOverride(double percent);
    // The IO page's 输出开/输出关 for OUT01-OUT21 (level 0/1). Refused while a program runs or
    // holds and in E-stop.
    bool setOutputByOperator(int port, int level);

    // Fault injection for training: input `pin` (1-24) stuck, delayed or bouncing from now on;
    // nullopt takes the fault off. `RunSettings::heldInputs` puts stuck faults on before a run.
    void setInputFault(int pin, std::optional<machine::InputFault> fault) { machine_.setInputFault(pin, fault); }
    // A trainer presses what is wired to input `pin` for a moment: it reads `level` for `seconds`.
    void pressInput(int pin, int level, double seconds) { machine_.pulseInput(pin, level, seconds); }

    // X, Y and Z always; the 4th and 5th axes when their home switch is set.
    std::vector<int> homeableAxes() const;
    static constexpr const char* kBootHomingPrompt = "是否进行开机寻零操作?";

    // The tool table as the panel edits it (ToolTableEdits.h): rows, an import, touch off.
    ToolTableEdits& toolTableEdits() { return toolEdits_; }
    const ToolTableEdits& toolTableEdits() const { return toolEdits_; }
    // Writes the table to the machine folder's tool.tbl atomically (and the M350's Z parameters
    // params.toml already lists, so both files agree; tool.tbl is the one read). nullopt on success.
    std::optional<std::string> saveToolTable(const files::AtomicWriteHooks& hooks = {});

    // Reads any variable as a macro would, for --print and the panel.
    macro::Value variable(int number);
    const gcode::Dialect& dialect() const { return *config_.dialect; }
    // The external output device (POPEN, DPRNT, BPRNT, PCLOS) and the Modbus slaves (ExternalDevices.h).
    ExternalDevices& externalDevices() { return devices_; }
    const ExternalDevices& externalDevices() const { return devices_; }
    // What the controller says as a run goes (StatusBoard.h): the messages, the #1503 status line, the trace.
    StatusBoard& status() { return status_; }
    const StatusBoard& status() const { return status_; }
    // The machine's configuration as it stands: parameters, offsets of the folder, the tool table now.
    config::MachineConfig config() const;

    // FANUC tool life management (ToolLifeCounter.h): the groups, the tool in use, the operator's reset.
    ToolLifeCounter& toolLife() { return toolLife_; }
    const ToolLifeCounter& toolLife() const { return toolLife_; }
    // Tool breakage (ToolBreakage.h): the spindle load as the PMC reads it, its monitor and history;
    // the tools as they really are (a break from RunSettings::toolBreaks shortens one at its time).
    const ToolBreakage& toolBreakage() const { return breakage_; }

    // macro::MachineAccess
    bool manageTools(macro::EvaluatedBlock& block) override;
    macro::Value readSystem(const macro::VariableInfo& info, int number) override;
    std::optional<std::string> writeSystem(const macro::VariableInfo& info, int number, double value,
                                           std::string_view text) override;
    std::optional<HomingFailure> builtInHoming(int axis) override;
    // machine::MachineObserver
    void onMachineEvent(const machine::MachineEvent& event) override;
    bool ignoresMove(const machine::Axes& from, const machine::Axes& to) const override;

private:
    void feedMagazine(const machine::MachineEvent& event);
    bool load(const gcode::SourceText& source, gcode::FileRole role);
    void applyParameterOverrides(); // --param, before anything reads the parameters
    void applySettings();
    void configureMachine();
    void syncToolLength() { breakage_.syncToolLength(); }
    void setUpBreakageWatch();
    void watchSpindleLoad(const machine::MachineEvent& event);
    void enterSafeState();
    void stepOnce();
    int stepOnce(int toolBefore); // the spindle tool after the step
    // True once what started at machine time `since` (a run, a hook, homing) ran longer than
    // --max-sim-time (or the clock went nan); the move or dwell under way is then stopped where the
    // limit found it, so the report shows that moment. Each run gets the whole limit.
    bool passedTimeLimit(double since);
    // Stops the motion under way at virtual time t (SimulatedMachine::interrupt); the magazine
    // learns where a move it was told of really stopped.
    machine::SimulatedMachine::Remainder interruptMotion(double t, bool immediate);
    // "the program ran 3600 s of simulated time without ending (stopped at 7250.5 s)": what ran
    // over the limit, and the machine time it stopped at.
    std::string timeLimitText(const std::string& what, double since) const;
    // The machine folder's params.toml, which native homing alarms name (their cause is a parameter).
    std::string parametersFile() const;
    void raiseAlarm(const Alarm& alarm);
    void parseWithLibraries(gcode::Program& program, const gcode::SourceText& source, gcode::FileRole role,
                            std::vector<gcode::Diagnostic>& diagnostics) const;
    static bool addSourceFile(gcode::Parser& parser, gcode::Program& program, const std::string& path,
                              gcode::FileRole role, std::vector<gcode::Diagnostic>& diagnostics);
    void addCalledHooks(gcode::Parser& parser, gcode::Program& program, const std::string& mainPath,
                        std::vector<gcode::Diagnostic>& diagnostics) const;
    std::unique_ptr<macro::Executor> newExecutor();
    std::optional<Alarm> runEventHook(config::Hook hook);
    std::optional<Alarm> runHookProgramToEnd(const std::string& name);
    void runPauseHook();
    void returnAfterPauseHook();
    KeyPress pressKey(int function, config::Hook hook, const std::string& key);
    // `since`: the machine time --max-sim-time counts from (the homing's or the run's start).
    std::optional<Alarm> homeAxis(int axis, double since);
    bool homeSwitchWired(int axis) const;
    int spindleTool() const { return magazine_.spindleTool(); }
    void stopForOperator(const interp::ModalInterpreter::OperatorStop& stop);
    bool optionalStopOn();
    void watchInput(int pin, int level);
    void pressStartIfAwaited(const params::PortAssignment& key, int pin, int level, const gcode::SourceLocation& where);
    std::optional<std::string> showDialog(double kind, std::string_view text);
    bool operatorAnswers() const { return settings_.operatorPresent && !pressStartWhenAwaited_; }

    config::MachineConfig config_;
    RunSettings settings_;
    interp::WorkOffsets offsets_;
    tools::ToolData tools_; // before interp_, which reads it
    tools::ToolData::Mark savedToolMark_;
    machine::SimulatedMachine machine_;
    machine::ScanMachine scan_{machine_}; // what the interpreter drives: machine_, or a scan of it
    interp::ModalInterpreter interp_;
    macro::VariableStore store_;
    gcode::Program program_;
    std::vector<gcode::Diagnostic> diagnostics_;
    std::unique_ptr<macro::Executor> executor_;
    std::array<int, machine::kAxisCount> homed_{};
    int fanucSpindleTool_ = 0;
    double dialogAnswer_ = 0.0;
    std::optional<Dialog> pendingDialog_; // see pendingDialog()
    double feedOverride_ = 100.0;
    double runStartedAt_ = 0.0;
    double timeLimitFrom_ = 0.0; // the run's start, moved on by its holds: --max-sim-time counts from here
    bool mdi_ = false;
    std::optional<config::Hook> hook_;  // the loaded program is this hook file
    bool inEventHook_ = false;          // pause.nc or error.nc runs: no hook starts inside it
    std::optional<machine::Axes> beforePauseHook_; // where the hold stopped the axes, if pause.nc moved them
    RunState state_ = RunState::Idle;
    std::optional<Alarm> alarm_;
    double displayTime_ = 0.0;
    machine::SimulatedMachine::Remainder remainder_; // what a hold cut short
    double liftedBy_ = 0.0;                          // Z lift of the hold (param 91, 70)
    std::string programStop_;                        // see programStop()
    SensorWatch sensorWatch_;
    bool pressStartWhenAwaited_ = false; // run(): no operator, the controller presses START
    void watchOperatorInputs();
    void placeHomeSwitches(); // Homing.cpp
    std::array<bool, 9> operatorInputActive_{}; // the operator inputs' last state (OperatorInputs.cpp)
    std::array<int, 9> operatorInputWiring_{};  // and the pin and level each was read on
    std::vector<OperatorKey> operatorKeys_;
    std::map<int, TraceSource> linkedInputSource_; // input -> the line that switched its output
    MagazineDriver magazine_; // the magazine device and its wiring (none when the folder has none)
    StatusBoard status_;      // before devices_, which writes to its trace
    ExternalDevices devices_; // the external output device and the Modbus slaves
    ToolLifeCounter toolLife_;
    ToolBreakage breakage_;   // the tools as they really are, the spindle load
    ToolTableEdits toolEdits_; // the panel's edits of tools_
    std::optional<std::pair<machine::SpindleState, double>> spindleBeforeHold_;

    // 断点加工 (StartAtLine.cpp): the main block a hold stopped, which pass over it, where it stopped
    struct PausePoint {
        std::uint32_t block = 0;
        std::uint64_t pass = 0;
        machine::Axes stoppedAt = machine::Axes::Zero();
        machine::SimulatedMachine::Remainder rest;
        bool mainMove = false; // the hold cut a move of that block itself, not of a call
        machine::Axes runFrom = machine::Axes::Zero(); // where the run began (G91 programs count from it)
    };
    std::optional<PausePoint> paused_;
    machine::Axes runStartedFrom_ = machine::Axes::Zero();
    void rememberPause(const machine::SimulatedMachine::Remainder& rest);
    bool startAt(std::uint32_t block, std::uint64_t pass, bool fromStopPoint, std::string* why);
    std::optional<std::string> scanTo(std::uint32_t block, std::uint64_t pass, bool through, const machine::Axes& from);
    bool inToolChange() const;
    std::string lineText(std::uint32_t block) const;
    void approach(const machine::Axes& target, machine::SpindleState spindle, double rpm);
    void continueRemainder(const machine::SimulatedMachine::Remainder& rest);

    // manual motion and the handwheel guide (ManualMotion.cpp, HandwheelGuide.cpp)
    ManualMotionState manual_;
    bool manualAllowed() const;
    bool jogging() const;
    bool moveManually(int axis, double distance, double speed, double acceleration);
    bool guideTurn(int multiplier, int detents, double seconds);
    double displayStep(double seconds);
};

} // namespace m350::controller
