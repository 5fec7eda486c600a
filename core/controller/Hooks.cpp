// Hook files: the machine folder's programs that the panel and the controller run when something
// happens (config/HookFiles.h names them), and the built-in O501 that the homing hooks call.
#include "core/controller/Controller.h"

#include "core/gcode/Parser.h"
#include "core/gcode/SourceText.h"

#include <filesystem>
#include <sstream>

namespace m350::controller {

bool Controller::hasHook(config::Hook hook) const { return config::hookPath(config_.folder, hook).has_value(); }

bool Controller::loadHook(config::Hook hook, const std::map<int, double>& variables) {
    const config::HookFile& file = config::hookFile(hook);
    auto say = [this, &file](const Message& why) {
        diagnostics_.assign(1, gcode::diagnostic(gcode::Severity::Error, gcode::DiagnosticKind::Syntax,
                                                 std::string(file.fileName), 0, 0, why));
        return false;
    };
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        // the running program stays loaded
        return say(message("hook_busy", {std::string(file.fileName)}));
    }
    auto path = config::hookPath(config_.folder, hook);
    if (!path || !file.runnable) {
        executor_.reset();
        hook_.reset();
        return say(message("hook_missing", {config_.folder, std::string(file.fileName), config::runsWhenWords(file)}));
    }
    if (!loadFile(*path)) {
        return false;
    }
    hook_ = hook;
    mdi_ = hook == config::Hook::Mdi; // mdi.nc is the MDI page's line: the panel is in MDI
    for (auto [number, value] : variables) {
        Message why;
        if (!setVariable(number, value, &why)) {
            executor_.reset();
            hook_.reset();
            diagnostics_.assign(1, gcode::diagnostic(gcode::Severity::Error, gcode::DiagnosticKind::Syntax,
                                                     std::string(file.fileName), 0, 0, why));
            return false;
        }
    }
    return true;
}

bool Controller::loadHookOrMdi(config::Hook hook, const std::map<int, double>& variables,
                               const std::vector<std::string>& fallback) {
    if (hasHook(hook)) {
        return loadHook(hook, variables);
    }
    if (!loadMdi(fallback)) {
        return false;
    }
    for (auto [number, value] : variables) {
        Message why;
        if (!setVariable(number, value, &why)) {
            executor_.reset();
            diagnostics_.push_back(gcode::diagnostic(gcode::Severity::Error, gcode::DiagnosticKind::Syntax, "MDI", 0, 0, why));
            return false;
        }
    }
    return true;
}

// ALL_T.nc is what M101 runs: its program (a file of blocks without an O number) becomes the M101
// handler, ahead of any O10101 in the machine's M library. Then the machine's libraries.
std::vector<LibraryCache::File> Controller::librariesFor(const std::string& mainPath) const {
    std::vector<LibraryCache::File> files;
    const int base = config_.dialect->mHandlerBase;
    auto path = config::hookPath(config_.folder, config::Hook::AllTools);
    std::error_code ec;
    if (base >= 0 && path && !std::filesystem::equivalent(*path, mainPath, ec)) {
        files.push_back({*path, gcode::FileRole::MLibrary, base + config::kAllToolsMCode});
    }
    for (const config::LibraryFile& library : config_.libraries) {
        files.push_back({library.path, library.role, -1});
    }
    return files;
}

// pause.nc and error.nc run beside the program they interrupt: the hook's program and executor
// take the place of the interrupted ones (which wait untouched) and run to the end at once in
// virtual time, over the same variables, interpreter and machine. Nobody answers inside: a dialog
// gets Enter and a wait for the extern START key gets it, as in run(). Returns the hook's alarm.
std::optional<Alarm> Controller::runEventHook(config::Hook hook) {
    auto path = config::hookPath(config_.folder, hook);
    if (inEventHook_ || scan_.scanning() || !path) {
        return std::nullopt;
    }
    const std::string name(config::hookFile(hook).fileName);
    auto source = gcode::readSourceFile(*path);
    if (auto* error = std::get_if<gcode::SourceReadError>(&source)) {
        const Message why{error->messageId, error->messageArguments};
        status_.postMessage(message("hook_not_run", {name, error->messageId.empty() ? error->message : bilingual(why)}));
        return std::nullopt;
    }
    const auto& text = std::get<gcode::SourceText>(source);
    gcode::Program program;
    std::vector<gcode::Diagnostic> diagnostics;
    parseWithLibraries(program, text, gcode::FileRole::Main, diagnostics);
    if (gcode::hasBlockingError(diagnostics)) {
        for (const gcode::Diagnostic& d : diagnostics) {
            if (d.severity == gcode::Severity::Error && d.kind == gcode::DiagnosticKind::Syntax) {
                const std::string where = bilingual(gcode::formatDiagnostic(d, MessageLanguage::English),
                                                    gcode::formatDiagnostic(d, MessageLanguage::Chinese));
                status_.postMessage(message("hook_not_run_syntax", {where, name}));
                break;
            }
        }
        return std::nullopt;
    }
    inEventHook_ = true;
    std::swap(program_, program);
    std::unique_ptr<macro::Executor> interrupted = std::exchange(executor_, newExecutor());
    std::optional<Alarm> alarm = runHookProgramToEnd(name);
    executor_ = std::move(interrupted);
    std::swap(program_, program);
    inEventHook_ = false;
    return alarm;
}

std::optional<Alarm> Controller::runHookProgramToEnd(const std::string& name) {
    auto unit = program_.mainUnit();
    if (!unit || !executor_->start(*unit)) {
        return std::nullopt;
    }
    if (status_.trace()) {
        status_.trace()->message(machine_.time(), name + " runs", status_.source());
    }
    const bool unattended = panel_.unattended();
    panel_.setUnattended(true);
    panel_.clearSensorWait();
    const double startedAt = machine_.time();
    while (executor_->state() == macro::Executor::State::Running) {
        if (passedTimeLimit(startedAt)) {
            std::vector<std::string> numbers = timeLimitNumbers(startedAt);
            const char* id = numbers.size() > 1 ? "time_limit_hook_since" : "time_limit_hook";
            numbers.insert(numbers.begin(), name);
            executor_->raise(AlarmCode::SimulatedTimeLimit, message(id, numbers));
            break;
        }
        stepOnce();
    }
    panel_.clearSensorWait();
    panel_.setUnattended(unattended);
    if (executor_->state() != macro::Executor::State::Alarmed) {
        return std::nullopt;
    }
    const Alarm& alarm = *executor_->alarm();
    std::ostringstream where;
    where << alarm.file << ':' << alarm.line << ':' << alarm.column << ": " << alarm.message;
    status_.postMessage(where.str() + " (alarm in " + name + ")");
    return alarm;
}

// PAUSE, M00, G04 P-1: pause.nc may move the axes (lift Z, park); START brings them back first (HoldMotion).
void Controller::runPauseHook() {
    const machine::Axes stoppedAt = machine_.position();
    std::optional<Alarm> alarm = runEventHook(config::Hook::Pause);
    holdMotion_.pauseHookRan(stoppedAt);
    if (alarm) {
        raiseAlarm(*alarm);
    }
}

// A library's O501 takes over the homing of `axis`: as the firmware's own homing, it starts by
// forgetting the axis's position (the homed marker goes out), so the soft limits no longer hold
// the axis while it searches for its switch (see checkAgainstSoftLimits).
void Controller::homingStarts(int axis) {
    if (!scan_.scanning()) {
        homing_.setHomed(axis, false);
    }
}

std::optional<macro::MachineAccess::HomingFailure> Controller::builtInHoming(int axis) {
    if (scan_.scanning()) {
        return HomingFailure{AlarmCode::NotHomed, message("homing_not_scanned")};
    }
    if (auto alarm = homing_.homeAxis(axis, timeLimitFrom_)) {
        return HomingFailure{alarm->code, Message{alarm->messageId, alarm->messageArguments}};
    }
    return std::nullopt;
}

} // namespace m350::controller
