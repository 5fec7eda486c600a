#include "core/controller/Controller.h"
#include "core/config/CallCodeParameters.h"
#include "core/controller/MachineSetup.h"
#include "core/controller/UnattendedOperator.h"
#include "core/params/FanucParameters.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace m350::controller {

Controller::Controller(config::MachineConfig config, RunSettings settings)
    : config_(std::move(config)), settings_(std::move(settings)),
      tools_(*config_.dialect, config_.parameters, std::exchange(config_.toolTable, std::nullopt)), machine_(settings_.trace || settings_.observer || config_.magazine.present() ? &machineEvents_ : nullptr),
      interp_(*config_.dialect, config_.parameters, offsets_, tools_, scan_), store_(*config_.dialect, config_.parameters, config_.variableLayout),
      machineEvents_({config_, settings_, machine_, magazine_, status_, toolLife_, breakage_, state_, executor_,
                      [this](double t) { interruptMotion(t, false); }}),
      magazine_({config_, settings_, machine_, interp_, handTool_.pmcRegister(), machineEvents_.inputSources(),
                 [this] { return status_.source(); }}),
      toolGuard_({*config_.dialect, config_.parameters, magazine_, executor_, [this](int number) { return variable(number); }}),
      status_({config_, machine_, interp_, magazine_, executor_, program_, diagnostics_, state_, alarm_, toolGuard_.doubt()}, settings_),
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
                     [this] { return interp_.state().selectedTool; }, [this] { return handTool_.tool(); },
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
        machine_.setObserver(&machineEvents_); // cutting time counts from the machine's feed events
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

// The machine's speeds, delays, switches and setters follow the parameters as they stand.
void Controller::configureMachine() {
    if (setUpMachine(machine_, config_)) {
        machine_.setObserver(&machineEvents_); // a rapid into the setter is a crash
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
            handTool_.set(*settings_.tool);
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

bool Controller::manageTools(macro::EvaluatedBlock& block) {
    toolGuard_.checkBlock(block);
    const bool took = toolLife_.applyBlock(block);
    if (toolLife_.manager().enabled()) {
        machine_.setObserver(&machineEvents_); // groups entered by G10 L3: cutting time counts from now on
        if (auto notice = toolLife_.manager().takeNotice()) {
            status_.postMessage(std::move(*notice));
        }
    }
    if (!took) {
        toolGuard_.checkToolWord(block);
    }
    return took;
}

void Controller::noteStopInChange() {
    if (!executor_ || !executor_->changingTool() ||
        (state_ != RunState::Running && state_ != RunState::Hold && state_ != RunState::Alarm)) {
        return;
    }
    if (auto notice = toolGuard_.stoppedInChange(handTool_.tool())) {
        status_.postMessage(*notice);
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
        machine_.setObserver(&machineEvents_); // the load follows every move; a break changes the tool's length
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

RunReport Controller::run() {
    panel_.setUnattended(true);
    start();
    UnattendedOperator unattended(settings_, runStartedAt_, state_ == RunState::Running);
    while (state_ == RunState::Running) {
        const UnattendedOperator::Press press = unattended.next();
        if (press.key == UnattendedOperator::Key::None) {
            advance(std::numeric_limits<double>::infinity());
        } else {
            advance(std::max(0.0, press.at - displayTime_));
            const bool eStop = press.key == UnattendedOperator::Key::EStop;
            if (state_ == RunState::Running || (eStop && state_ == RunState::Hold)) {
                status_.postMessage(unattended.pressed(press, status_.source()));
                eStop ? emergencyStop() : hold();
            }
        }
        if (state_ == RunState::Hold) {
            if (!unattended.startAfterHold(machine_.position())) {
                const TraceSource source = status_.source();
                raiseAlarm(Alarm::of(AlarmCode::SimulatedTimeLimit, unattended.loopWords(source), source.file,
                                     source.line, 1));
                break;
            }
            status_.postMessage(programStop_.text().empty() ? message("notice_start_after_pause")
                                                            : programStop_.startWords());
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
    machineEvents_.forgetCrash();
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
    if (auto changed = interp_.takeToolChange(); changed && !magazine_.device()) [[unlikely]] {
        handTool_.take(*changed);
    }
    if (interp_.hasReloadIssues()) [[unlikely]] {
        for (std::string& issue : interp_.takeReloadIssues()) {
            status_.postMessage(message("tool_table_reload_issue", {std::move(issue)}));
        }
    }
    if (auto stop = interp_.takeStop()) {
        if (inEventHook_) {
            status_.postMessage(message("notice_start_in_hook", {ProgramStop::bilingualWhat(stop->what)}));
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
    if (!toolGuard_.lengthLookedAt(toolAfter) && machine_.spindleTurning()) [[unlikely]] {
        if (auto warning = toolGuard_.toolTurns(toolAfter, status_.source())) {
            status_.warn(*warning);
        }
    }
    if (toolAfter != toolBefore) {
        syncToolLength();
        if (status_.trace()) {
            status_.trace()->toolChange(machine_.time(), toolBefore, toolAfter, status_.source());
        }
    }
    return toolAfter;
}

void Controller::stopForOperator(const interp::ModalInterpreter::OperatorStop& stop) {
    if (stop.kind == interp::ModalInterpreter::OperatorStop::Kind::Optional && !optionalStopOn()) {
        return;
    }
    TraceSource where{program_.fileName(stop.location), stop.location.line};
    programStop_.stoppedBy(stop.what, where);
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
