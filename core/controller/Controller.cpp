#include "core/controller/Controller.h"
#include "core/config/CallCodeParameters.h"
#include "core/params/FanucParameters.h"

#include "core/params/IoPorts.h"
#include "core/common/Numeric.h"

#include "core/params/ParameterLimits.h"
#include "core/params/ParameterNumbers.h"
#include "core/devices/Magazine.h"
#include "core/macro/MacroError.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace m350::controller {

namespace {

std::string shortSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", seconds);
    return text;
}

// What stopped the program (ModalInterpreter::stopForOperator), in both languages.
std::string stopWords(const std::string& what) {
    if (what == "M00 program stop") return bilingual(what, "M00 程序停止");
    if (what == "M01 optional stop") return bilingual(what, "M01 选择停止");
    if (what == "G04 P-1 waits for START") return bilingual(what, "G04 P-1 等待循环启动");
    return what;
}

} // namespace

Controller::Controller(config::MachineConfig config, RunSettings settings)
    : config_(std::move(config)), settings_(std::move(settings)),
      tools_(*config_.dialect, config_.parameters, std::exchange(config_.toolTable, std::nullopt)), machine_(settings_.trace || settings_.observer || config_.magazine.present() ? this : nullptr),
      interp_(*config_.dialect, config_.parameters, offsets_, tools_, scan_), store_(*config_.dialect, config_.parameters, config_.variableLayout),
      magazine_({config_, settings_, machine_, interp_, fanucSpindleTool_, linkedInputSource_,
                 [this] { return status_.source(); }}),
      status_({config_, machine_, interp_, magazine_, executor_, program_, diagnostics_, state_, alarm_, toolDoubt_}, settings_),
      devices_({config_.parameters, scan_, status_.traceWriter(), [this] { return machine_.time(); },
                [this] { return status_.source(); }, [this](double seconds) { machine_.dwell(seconds); }},
               config_.modbus, settings_.externalOutputLimit),
      toolLife_(config_.toolLife, state_, executor_, *config_.dialect, scan_), breakage_(machine_, magazine_),
      toolEdits_({tools_, state_, [this] { return manual_.jogging(); }, config_, interp_, machine_, magazine_}),
      panel_(newOperatorPanel()),
      interfacePmc_({config_.interfaceSignals, scan_,
                     [this](int pin) {
                         const int level = machine_.input(pin);
                         panel_.readInput(pin, level);
                         return level;
                     },
                     [this] { return interp_.state().selectedTool; }, [this] { return fanucSpindleTool_; },
                     [this] { return breakage_.spindleLoad().reg(); },
                     [this] { return toolLife_.manager().toolChangeSignal(); },
                     [this] { return toolLife_.manager().newToolSignal(); }}),
      singleBlock_(settings_.singleBlock) {
    tools_.setOffsetMemory(config_.offsetMemory);
    if (config_.dialect->id == gcode::DialectId::Fanuc && !config_.toolTableFile.empty()) {
        tools_.setSourceFile(config_.toolTableFile);
    }
    interp_.setSpindleToolSource([this] { return spindleTool(); });
    offsets_.setAdditionalCount(config_.additionalWorkSystems());
    interp_.setCoordinateFeatures({config_.additionalWorkSystems(), config_.rotation()});
    for (int slot = 0; slot < interp::WorkOffsets::kSlots; ++slot) {
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            offsets_.set(slot, axis, config_.offsets[static_cast<std::size_t>(slot)][static_cast<std::size_t>(axis)]);
        }
    }
    for (const machine::IoLink& link : config_.ioLinks) {
        machine_.addLink(link);
    }
    interp_.setHomedFlags(&homing_.flags());
    for (const auto& [number, position] : config_.referencePoints) {
        interp_.setReferencePoint(number, Eigen::Map<const machine::Axes>(position.data()));
    }
    if (toolLife_.manager().enabled()) {
        machine_.setObserver(this); // cutting time counts from the machine's feed events
    }
    applyParameterOverrides();
    if (toolLife_.manager().data().fromParameters) {
        toolLife_.manager().applyFanucParameters(config_.fanucParameters); // --param 6800 ... too
    }
    setUpBreakageWatch();
    applySettings();
    breakage_.startAt(machine_.time());
    toolEdits_.markSaved(tools_.mark());
    writes_.take(config_.parameters); // what the folder and --param set is where the log starts
}

Controller::~Controller() = default;

OperatorPanel Controller::newOperatorPanel() {
    auto post = [this](const Message& words) { status_.postMessage(words); };
    OperatorDialog::Context dialog{
        post,
        [this](std::string text) {
            status_.showStatus(text);
            status_.postMessage(std::move(text));
        },
        [this](std::string text) {
            if (status_.trace()) status_.trace()->message(machine_.time(), text, status_.source());
        },
        [this] {
            if (machine_.time() < displayTime_) machine_.blockTime(displayTime_ - machine_.time());
        }};
    UserKeys::Context keys{
        config_.parameters,
        [this](int port) { return machine_.output(port); },
        [this](int port, int level) { return manual_.setOutputByOperator(port, level); },
        [this](config::Hook hook) { return loadHook(hook); },
        [this](config::Hook hook, const std::map<int, double>& variables, const std::vector<std::string>& fallback) {
            return loadHookOrMdi(hook, variables, fallback);
        },
        [this]() -> const std::vector<gcode::Diagnostic>& { return diagnostics_; },
        [this](std::string why) {
            diagnostics_.assign(1, {gcode::Severity::Error, gcode::DiagnosticKind::Syntax, "", 0, 0, std::move(why)});
            executor_.reset();
        }};
    InputWatch::Context inputs{config_.parameters,
                               settings_,
                               machine_,
                               program_,
                               status_.traceWriter(),
                               [this] { return executor_ ? executor_->location() : std::nullopt; },
                               [this](int pin) {
                                   return bilingual(magazine_.describeInput(pin), magazine_.describeInput(pin, true));
                               },
                               post};
    return OperatorPanel({settings_, [this] { return state_ == RunState::Running; }}, std::move(dialog),
                         std::move(keys), std::move(inputs));
}

config::MachineConfig Controller::config() const {
    config::MachineConfig out = config_;
    out.toolTable = tools_.table();
    out.toolLife = toolLife_.manager().data(); // a 仿真 run selects the sister tools the machine would
    return out;
}

// The machine's speeds, delays and spindle sensor, from the parameters as they stand.
void Controller::configureMachine() {
    const params::ParameterTable& p = config_.parameters;
    machine::MotionLimits limits;
    auto positive = [](double v, double fallback) { return v > 0.0 ? v : fallback; };
    limits.rapidSpeed = positive(p.get(param::kRapidSpeed), 10000.0) / 60.0;
    limits.maxSpeed = positive(p.get(param::kMaxSpeed), 12000.0) / 60.0;
    limits.feedAcceleration = positive(p.get(param::kFeedAcceleration), 500.0);
    limits.rapidAcceleration = positive(p.get(param::kRapidAcceleration), limits.feedAcceleration);
    limits.spindleStartDelay = std::max(0.0, p.get(param::kSpindleStartDelay));
    limits.spindleStopDelay = std::max(0.0, p.get(param::kSpindleStopDelay));
    limits.maxSpindleRpm = positive(p.get(param::kMaxSpindleRpm), 24000.0);
    machine_.setLimits(limits);
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        machine::HomeSwitch homeSwitch = machine_.homeSwitch(axis); // it stays where it is
        auto home = params::wiredInput(p, param::kHomeSwitchX + 3 * axis);
        homeSwitch.port = home ? home->pin : 0;
        homeSwitch.activeLevel = home ? home->activeLevel : 0;
        machine_.setHomeSwitch(axis, homeSwitch);
    }
    machine::ToolSetter setter;
    if (auto input = params::wiredInput(p, param::kFixedSetterInput)) {
        setter.port = input->pin;
        setter.activeLevel = input->activeLevel;
    }
    setter.x = p.get(param::kFixedSetterX);
    setter.y = p.get(param::kFixedSetterX + 1);
    setter.top = config_.setterTop;
    setter.radius = config_.setterRadius;
    machine_.setToolSetter(setter);
    if (setter.port != 0) {
        machine_.setObserver(this); // a rapid into the setter is a crash (checkSetterRapid)
    }
    machine::ToolSetter block; // the floating setter, where the machine folder puts one on the work
    if (auto input = params::wiredInput(p, param::kFloatingSetterInput); input && config_.floatingSetterTop) {
        block.port = input->pin;
        block.activeLevel = input->activeLevel;
        block.top = *config_.floatingSetterTop;
    }
    machine_.setFloatingSetter(block);
    if (auto stopped = params::wiredInput(p, param::kSpindleStoppedInput)) {
        machine_.setSpindleStoppedSensor({stopped->pin, stopped->activeLevel});
    }
}

void Controller::applyParameterOverrides() {
    bool fanuc = false;
    for (auto [number, value] : settings_.parameters) {
        if (params::isFanucParameterNumber(number)) {
            config_.fanucParameters[number] = value;
            config_.fanucParameterOrigins[number] = "--param " + std::to_string(number);
            fanuc = true;
        } else if (params::ParameterTable::valid(number)) {
            config_.parameters.set(number, value);
        }
    }
    if (fanuc) {
        // m350-sim refuses such a clash before it builds a controller; here the folder's table stays
        if (auto refused = config::rebuildCallCodes(config_)) {
            status_.postMessage(message("call_codes_kept", {bilingual(refused->message)}));
        }
    }
}

void Controller::applySettings() {
    writes_.setLevel(settings_.userLevel);
    for (auto [port, level] : settings_.heldInputs) {
        machine_.forceInput(port, level);
    }
    for (const auto& [port, fault] : settings_.inputFaults) {
        machine_.setInputFault(port, fault);
    }
    if (settings_.tool) {
        if (config_.dialect->id == gcode::DialectId::M350) {
            config_.parameters.set(param::kCurrentTool, *settings_.tool);
        } else {
            fanucSpindleTool_ = *settings_.tool;
            interp_.state().selectedTool = *settings_.tool;
        }
    }
    // the modal defaults that come from parameters, after --param
    interp_.state().feed = config_.parameters.get(param::kDefaultFeed);
    interp_.state().spindleSpeed = config_.parameters.get(param::kDefaultSpindleSpeed);
    configureMachine();
    magazine_.build();
    syncToolLength();
    machine::Axes start = machine::Axes::Zero();
    if (settings_.homed) {
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            start(axis) = config_.parameters.get(param::kHomePositionX + axis);
        }
    }
    machine_.setPosition(start);
    homing_.startUp(settings_.homed, config_.homeSwitchDistance);
    for (auto [number, value] : config_.variables) {
        store_.write(store_.map().describe(number), number, macro::Value::of(value));
    }
}

void Controller::onMachineEvent(const machine::MachineEvent& event) {
    if (status_.trace()) {
        // an input an IoLink drives changes because of the output switch that came before it
        TraceSource where = status_.source();
        if (event.type == machine::MachineEvent::Type::Io && event.port < 0) {
            if (auto it = linkedInputSource_.find(-event.port); it != linkedInputSource_.end()) {
                where = it->second;
            }
        } else if (event.type == machine::MachineEvent::Type::Io) {
            for (const machine::IoLink& link : config_.ioLinks) {
                if (link.output == event.port) {
                    linkedInputSource_[link.input] = where;
                }
            }
        }
        status_.trace()->machineEvent(event, where);
    }
    if (settings_.observer) {
        settings_.observer->onMachineEvent(event);
    }
    try {
        if (event.type == machine::MachineEvent::Type::Rapid) {
            checkSetterRapid(event);
        }
        if (magazine_.device()) {
            feedMagazine(event);
        }
    } catch (const macro::MacroError& error) {
        // a move that runs into the hardware: where it was going is where it hits (the machine view
        // marks it there; the axes stop where they are when the alarm comes)
        const bool move = event.type == machine::MachineEvent::Type::Rapid ||
                          event.type == machine::MachineEvent::Type::Feed || event.type == machine::MachineEvent::Type::Arc;
        crashPlace_ = error.code == AlarmCode::Crash && move ? std::optional<machine::Axes>(event.to) : std::nullopt;
        throw;
    }
    toolLife_.countCuttingTime(event);
    // nothing to sample, nothing that breaks: the common case, every move of a program
    if (breakage_.active()) {
        watchSpindleLoad(event);
    }
}

// Nothing listens to a straight move but a linear rack, which it passes wide of: no trace, no
// observer, no cutting time counted, no spindle load or breakage to follow. Most moves of a program.
bool Controller::ignoresMove(const machine::Axes& from, const machine::Axes& to) const {
    return !status_.trace() && !settings_.observer && !toolLife_.manager().inUse() && !breakage_.active() &&
           (!magazine_.device() || magazine_.ignores(from, to)) &&
           machine_.setterPenetration(from, to) <= kSetterContact;
}

// The fixed setter is solid (the M350's 对刀仪, a FANUC's TS27R stylus): a rapid that drives the
// tool below its trip point hits it, as a move into a rack pocket does. Only G31 may meet it.
void Controller::checkSetterRapid(const machine::MachineEvent& event) {
    const double depth = machine_.setterPenetration(event.from, event.to);
    if (depth <= kSetterContact) {
        return;
    }
    char mm[32];
    std::snprintf(mm, sizeof mm, "%.3f", depth);
    const std::string tool = std::to_string(spindleTool());
    macro::MacroError crash = macro::MacroError::of(AlarmCode::Crash, message("setter_crash", {tool, mm}));
    if (state_ == RunState::Alarm || state_ == RunState::EStop) {
        status_.postMessage(Message{crash.messageId, crash.messageArguments}); // the first alarm stays the one shown
        return;
    }
    throw crash;
}

bool Controller::manageTools(macro::EvaluatedBlock& block) {
    if (block.has('T')) [[unlikely]] {
        lastToolWord_ = roundToInt(block.words[block.firstOf['T' - 'A']].value);
    }
    if (toolDoubt_.doubt()) [[unlikely]] {
        refuseChangeInDoubt(block);
    }
    const bool took = toolLife_.applyBlock(block);
    if (toolLife_.manager().enabled()) {
        machine_.setObserver(this); // groups entered by G10 L3: cutting time counts from now on
        if (auto notice = toolLife_.manager().takeNotice()) {
            status_.postMessage(std::move(*notice));
        }
    }
    if (!took && magazine_.device() && (block.has('T') || block.mCodes.has(61))) [[unlikely]] {
        checkToolWord(block);
    }
    return took;
}

// The T code goes to the PMC as the block starts (FANUC's T strobe), before its motion and before
// M06 calls the change program: a T the magazine cannot serve is refused there, at the T word. A T
// that is a macro's argument (G65/G66 P.. T..) selects nothing.
void Controller::checkToolWord(const macro::EvaluatedBlock& block) const {
    if (block.mCodes.has(61)) {
        const auto m61 = std::find_if(block.words.begin(), block.words.end(),
                                      [](const macro::WordValue& w) { return w.letter == 'M' && w.value == 61.0; });
        throw macro::MacroError::of(AlarmCode::InvalidWord, message("m61_with_magazine"), m61->column);
    }
    if (block.gCodes.has(65) || block.gCodes.has(66) || block.otherCodes) {
        return;
    }
    const macro::WordValue& t = block.words[block.firstOf['T' - 'A']];
    if (auto why = magazine_.refusedTool(roundToInt(t.value))) {
        throw macro::MacroError::of(AlarmCode::InvalidArgument, *why, t.column);
    }
}

// After a stop in a change, the next change (an M350's T, a FANUC's M06) would start from a tool
// the controller only believes is in the spindle: refused at its word until the operator says.
void Controller::refuseChangeInDoubt(const macro::EvaluatedBlock& block) const {
    if (!magazine_.device() || (executor_ && executor_->changingTool()) || block.gCodes.has(65) ||
        block.gCodes.has(66)) {
        return;
    }
    const bool m350 = config_.dialect->id == gcode::DialectId::M350;
    const auto word = std::find_if(block.words.begin(), block.words.end(), [m350](const macro::WordValue& w) {
        return m350 ? w.letter == 'T' : w.letter == 'M' && w.value == 6.0;
    });
    if (word != block.words.end()) {
        throw macro::MacroError::of(AlarmCode::InvalidArgument, toolDoubt_.refusal(), word->column);
    }
}

void Controller::noteStopInChange() {
    if (!executor_ || !executor_->changingTool() ||
        (state_ != RunState::Running && state_ != RunState::Hold && state_ != RunState::Alarm)) {
        return;
    }
    const bool m350 = config_.dialect->id == gcode::DialectId::M350;
    const macro::Value target = m350 ? variable(1504) : macro::Value::of(lastToolWord_);
    const int recorded = m350 ? saturatingInt(config_.parameters.get(param::kCurrentTool)) : fanucSpindleTool_;
    if (toolDoubt_.stoppedInChange(target.vacant ? 0 : roundToInt(target.number), recorded)) {
        status_.postMessage(toolDoubt_.notice());
    }
}

// Tool breakage in the simulated world and the spindle load monitor (the FANUC article's second
// method): the load is sampled as virtual time passes and an anomaly stops the run like any alarm.
void Controller::setUpBreakageWatch() {
    if (config_.spindleLoad) {
        config_.spindleLoad->lambda =
            params::fanucParameter(config_.fanucParameters, params::kLoadMeterFullScale);
    }
    breakage_.setUp(config_, settings_);
    if (breakage_.active()) {
        machine_.setObserver(this); // the load follows every move; a break changes the tool's length
    }
}

void Controller::watchSpindleLoad(const machine::MachineEvent& event) {
    auto anomaly = breakage_.sample(event);
    if (anomaly && state_ == RunState::Running && executor_) {
        interruptMotion(anomaly->time, false); // the axes brake from where they were then
        throw macro::MacroError::of(AlarmCode::SpindleLoad, anomaly->message);
    }
}

// The magazine sees every event, also the safe state an alarm drives the outputs to (the drawbar
// clamps, the heads go up): what it holds must follow. Once an alarm stands, what the hardware
// suffers besides is a message, the first alarm stays the one shown.
void Controller::feedMagazine(const machine::MachineEvent& event) {
    if (state_ != RunState::Alarm && state_ != RunState::EStop) {
        magazine_.onMachineEvent(event);
        return;
    }
    try {
        magazine_.onMachineEvent(event);
    } catch (const macro::MacroError& error) {
        if (error.messageId.empty()) {
            status_.postMessage(error.message);
        } else {
            status_.postMessage(Message{error.messageId, error.messageArguments});
        }
    }
}

// Alarms stop motion and drive every output to its safe (off) state, as the real controller does.
// An output's safe state is its function's inactive level (tool clamped, magazine in, cover
// closed); an output with no function is switched off.
void Controller::enterSafeState() {
    machine_.spindle(machine::SpindleState::Stop, 0.0);
    machine_.coolant(false);
    for (int port = 1; port <= machine::kOutputCount; ++port) {
        auto function = params::outputOnPin(config_.parameters, port);
        machine_.setOutput(port, function ? 1 - function->activeLevel : 0);
    }
}

namespace {

// Holds in a row, with the machine standing still between them, that an unattended run answers
// with START before it takes them for a loop only an operator can end (`N1 M00` / `GOTO1`). Far
// above any program's inspection stops in a loop, and reached in about a second (4 s of virtual time).
constexpr int kMostIdleHolds = 20000;

} // namespace

RunReport Controller::run() {
    panel_.setUnattended(true);
    start();
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const bool running = state_ == RunState::Running;
    double pauseAt = settings_.pauseAt && running ? runStartedAt_ + *settings_.pauseAt : kNever;
    double estopAt = settings_.estopAt && running ? runStartedAt_ + *settings_.estopAt : kNever;
    std::optional<machine::Axes> heldAt; // where the machine stood at the last hold
    int idleHolds = 0;                   // holds in a row with no move between them
    while (state_ == RunState::Running) {
        if (estopAt != kNever && estopAt < pauseAt) {
            advance(std::max(0.0, estopAt - displayTime_));
            if (state_ == RunState::Running || state_ == RunState::Hold) {
                status_.postMessage(message("notice_estop_pressed", {shortSeconds(estopAt - runStartedAt_),
                                                                      status_.source().file,
                                                                      std::to_string(status_.source().line)}));
                emergencyStop();
            }
            estopAt = kNever;
        } else if (pauseAt != kNever) {
            advance(std::max(0.0, pauseAt - displayTime_));
            if (state_ == RunState::Running) {
                status_.postMessage(message("notice_pause_pressed", {shortSeconds(pauseAt - runStartedAt_),
                                                                      status_.source().file,
                                                                      std::to_string(status_.source().line)}));
                hold();
            }
            pauseAt = kNever;
        } else {
            advance(std::numeric_limits<double>::infinity());
        }
        if (state_ == RunState::Hold) {
            // `N1 M00` / `GOTO1` holds forever and costs no virtual time: holds over and over with
            // the machine standing still wait on an operator this run has not got
            const machine::Axes at = machine_.position();
            idleHolds = heldAt && (*heldAt - at).cwiseAbs().maxCoeff() == 0.0 ? idleHolds + 1 : 1;
            heldAt = at;
            if (idleHolds > kMostIdleHolds) {
                const TraceSource source = status_.source();
                raiseAlarm(Alarm::of(AlarmCode::SimulatedTimeLimit,
                                     message("operator_loop", {source.file, std::to_string(source.line),
                                                               std::to_string(kMostIdleHolds)}),
                                     source.file, source.line, 1));
                break;
            }
            status_.postMessage(programStop_.empty()
                                    ? message("notice_start_after_pause")
                                    : programStopWords_);
            displayTime_ = machine_.time(); // START comes the moment the machine stands still
            resume();
        }
    }
    panel_.setUnattended(false);
    if (status_.trace()) {
        machine_.reportLinkedInputs(machine_.time());
    }
    return status_.report();
}

bool Controller::start() {
    if (manual_.jogging()) {
        return false; // START waits for the manual move to end
    }
    alarm_.reset();
    panel_.clearDialog();
    panel_.clearSensorWait();
    breakRun_.forgetPause();
    devices_.beginRun();
    if (!executor_) {
        setState(RunState::Idle);
        return false;
    }
    if (!mdi_ && !hook_ && config_.parameters.get(param::kHomeBeforeProcessing) != 0.0 &&
        !homing_.xyzHomed()) {
        // param 220: automatic runs need X, Y and Z homed (MDI does not)
        raiseAlarm(Alarm::of(AlarmCode::NotHomed, message("not_homed_auto"),
                             program_.files.empty() ? std::string() : program_.files.front().name));
        return false;
    }
    resetOperationControl();
    auto unit = program_.mainUnit();
    toolLife_.manager().startRun();
    displayTime_ = machine_.time();
    runStartedAt_ = displayTime_;
    runMovesFrom_ = machine_.movesMade();
    crashPlace_.reset();
    timeLimitFrom_ = runStartedAt_;
    breakRun_.runStartsFrom(machine_.position());
    if (!unit || !executor_->start(*unit)) {
        setState(RunState::Finished);
        return true;
    }
    setState(RunState::Running);
    return true;
}

Controller::RunState Controller::advance(double seconds) {
    displayTime_ += manual_.displayStep(seconds); // the handwheel guide may slow it, stop it or run it back
    if (auto eStop = panel_.watchInputs(config_.parameters, machine_, state_ == RunState::Running);
        eStop && state_ != RunState::EStop) {
        emergencyStop(*eStop);
    }
    if (state_ != RunState::Running) {
        // Between runs the machine's clock follows the display's, so what devices drive in time
        // (a clamp cylinder the operator switched from the IO page) arrives while the panel watches.
        if (state_ != RunState::Hold && std::isfinite(displayTime_) && machine_.time() < displayTime_) {
            machine_.blockTime(displayTime_ - machine_.time());
        }
        return state_;
    }
    int tool = spindleTool(); // nothing between two steps changes it: each step's is the next one's
    while (state_ == RunState::Running && executor_->state() == macro::Executor::State::Running &&
           machine_.time() <= displayTime_ && !panel_.dialogPending()) {
        if (passedTimeLimit(timeLimitFrom_)) {
            const std::vector<std::string> numbers = timeLimitNumbers(timeLimitFrom_);
            const bool since = numbers.size() > 1;
            executor_->raise(AlarmCode::SimulatedTimeLimit, message(since ? "time_limit_program_since" : "time_limit_program", numbers));
            break;
        }
        tool = stepOnce(tool);
    }
    if (executor_->state() == macro::Executor::State::Alarmed) {
        raiseAlarm(*executor_->alarm());
    } else if (executor_->state() == macro::Executor::State::Finished) {
        setState(RunState::Finished);
    }
    return state_;
}

void Controller::stepOnce() {
    stepOnce(spindleTool());
}

int Controller::stepOnce(int toolBefore) {
    std::uint64_t blocksBefore = executor_->blocksExecuted();
    const std::uint64_t machineBlocksBefore = executor_->machineBlocksExecuted();
    executor_->step();
    if (executor_->blocksExecuted() != blocksBefore) {
        machine_.blockTime(settings_.blockTime);
    }
    if (auto changed = interp_.takeToolChange()) [[unlikely]] {
        takeToolChange(*changed);
    }
    if (interp_.hasReloadIssues()) [[unlikely]] {
        for (std::string& issue : interp_.takeReloadIssues()) {
            status_.postMessage(message("tool_table_reload_issue", {std::move(issue)}));
        }
    }
    if (auto stop = interp_.takeStop()) {
        if (inEventHook_) {
            status_.postMessage(message("notice_start_in_hook", {stopWords(stop->what)}));
        } else {
            stopForOperator(*stop);
        }
    }
    if ((singleBlock_ || holdPending_) && !inEventHook_) {
        stopAfterStep(machineBlocksBefore);
    }
    if (interp_.hasLookAheadChanges()) {
        for (const std::string& code : interp_.takeLookAheadChanges()) {
            if (status_.trace()) {
                status_.trace()->lookAhead(machine_.time(), code, status_.source());
            }
        }
    }
    const int toolAfter = spindleTool();
    if (toolAfter != lengthCheckedTool_ && machine_.spindleTurning()) [[unlikely]] {
        checkToolLength(toolAfter);
    }
    if (toolAfter != toolBefore) {
        syncToolLength();
        if (status_.trace()) {
            status_.trace()->toolChange(machine_.time(), toolBefore, toolAfter, status_.source());
        }
    }
    return toolAfter;
}

// A FANUC M06 the interpreter ran (no changer: the operator's change by hand) or LinuxCNC's M61:
// the spindle's tool is the one named. LinuxCNC's random changer puts the old tool into the new
// one's pocket at M06.
void Controller::takeToolChange(const interp::ModalInterpreter::ToolChange& change) {
    if (magazine_.device()) {
        return; // the magazine knows what the spindle holds
    }
    if (!change.byHand && config_.randomToolChanger) {
        tools_.swapPockets(fanucSpindleTool_, change.tool);
    }
    fanucSpindleTool_ = change.tool;
}

// On the M350 with its fixed setter on (param 130) every tool is set (对刀) before it cuts: its Z
// offset (params 930-945, a virtual tool's 973-992) is where it trips the setter, and one never set
// leaves work Z wrong by the whole tool length. The spindle turning with such a tool warns once per
// tool. Without the fixed setter an offset of 0 is how the manual's single-tool 清零 works.
void Controller::checkToolLength(int tool) {
    lengthCheckedTool_ = tool;
    if (config_.dialect->id != gcode::DialectId::M350 || tool == 0 ||
        config_.parameters.get(param::kFixedSetterValid) == 0.0 || !lengthWarned_.insert(tool).second) {
        return;
    }
    const std::optional<int> parameter = tools::m350ZParameter(tool, config_.parameters);
    if (!parameter || config_.parameters.get(*parameter) != 0.0) {
        return;
    }
    const std::string t = std::to_string(tool);
    const std::string p = std::to_string(*parameter);
    const TraceSource where = status_.source();
    Alarm warning;
    warning.code = AlarmCode::InvalidArgument;
    warning.message = "T" + t + " turns with no Z offset (param " + p + " = 0): set the tool before it cuts";
    warning.file = where.file;
    warning.line = where.line;
    warning.messageId = "tool_length_unset";
    warning.messageArguments = {t, p};
    status_.warn(warning);
}

void Controller::stopForOperator(const interp::ModalInterpreter::OperatorStop& stop) {
    if (stop.kind == interp::ModalInterpreter::OperatorStop::Kind::Optional && !optionalStopOn()) {
        return;
    }
    TraceSource where{program_.fileName(stop.location), stop.location.line};
    programStop_ = stop.what + " (" + where.file + ":" + std::to_string(where.line) + ")";
    const std::string place = " (" + where.file + ":" + std::to_string(where.line) + ")";
    programStopWords_ = message("notice_start_after_stop",
                                {bilingual(programStop_, argumentIn(stopWords(stop.what), MessageLanguage::Chinese) + place)});
    setState(RunState::Hold);
    if (status_.trace()) {
        status_.trace()->programStop(machine_.time(), stop.what, where);
    }
    runPauseHook();
}

bool Controller::optionalStopOn() {
    if (settings_.optionalStop) {
        return true;
    }
    if (config_.dialect->id == gcode::DialectId::M350) {
        macro::Value m1 = variable(1500); // M1 使能 on the M350
        return !m1.vacant && m1.number != 0.0;
    }
    return false;
}

void Controller::raiseAlarm(const Alarm& alarm) {
    noteStopInChange(); // before the state says Alarm: an alarm inside a change stops it too
    alarm_ = alarm;
    events_.alarm(machine_.time(), alarm);
    panel_.clearDialog();
    if (executor_ && executor_->changingTool()) {
        toolLife_.manager().revertChange(); // the change never completed: its tool is not in use
    }
    setState(RunState::Alarm);
    enterSafeState();
    if (status_.trace()) {
        status_.trace()->alarm(machine_.time(), alarm);
    }
    if (alarm.code != AlarmCode::EmergencyStop) {
        runEventHook(config::Hook::Error); // its own alarm is only a message: the first one stands
    }
}

void Controller::setState(RunState next) {
    if (next == RunState::Finished && state_ != RunState::Finished) {
        const auto unit = program_.mainUnit();
        const bool named = unit && !mdi_; // a hook file (T.nc) by its name too
        events_.finished(machine_.time(), named ? program_.files[program_.units[*unit].file].name : std::string());
    }
    state_ = next;
}

} // namespace m350::controller
