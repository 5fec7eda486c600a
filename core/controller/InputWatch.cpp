// The sensor-wait watchdog: a macro that keeps reading an input that never changes is waiting for a
// sensor. The real controller would hang there; the simulator says which input, and after
// RunSettings::sensorTimeout of virtual time stops with an alarm naming it.
#include "core/controller/Controller.h"

#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"
#include "core/macro/MacroError.h"

#include <cstdio>

namespace m350::controller {

namespace {

// The operator's own inputs (extern keys, START, PAUSE, E-stop): waiting for a person is no fault.
bool operatorInput(const std::optional<params::PortAssignment>& a) {
    return a && a->function->parameter >= 581 && a->function->parameter <= 605;
}

constexpr double kKeyPress = 0.3; // how long a pressed key stays down, s

std::string seconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", s);
    return buffer;
}

} // namespace

void Controller::watchInput(int pin, int level) {
    if (!executor_) {
        return;
    }
    auto where = executor_->location();
    auto function = params::inputOnPin(config_.parameters, pin);
    if (!where) {
        return;
    }
    if (operatorInput(function)) {
        pressStartIfAwaited(*function, pin, level, *where);
        return;
    }
    switch (sensorWatch_.read(pin, level, machine_.time(), *where, settings_.sensorTimeout)) {
    case SensorWatch::Verdict::Reading:
    case SensorWatch::Verdict::Waiting: return;
    case SensorWatch::Verdict::WaitBegins:
        if (status_.trace()) {
            status_.trace()->sensorWait(machine_.time(), params::inputName(pin), 1 - level,
                               {program_.fileName(*where), where->line});
        }
        return;
    case SensorWatch::Verdict::TimedOut: {
        std::string what = magazine_.describeInput(pin) + " never became " +
                           std::to_string(1 - level) + ": waited " + seconds(settings_.sensorTimeout) + " s at " +
                           program_.fileName(*where) + ":" + std::to_string(where->line);
        sensorWatch_.clear();
        throw macro::MacroError{AlarmCode::SensorTimeout, std::move(what), 0};
    }
    }
}

// A run without an operator (run()) presses the extern START key when a macro waits for it, as
// the operator would after doing what the prompt asked, and says so.
void Controller::pressStartIfAwaited(const params::PortAssignment& key, int pin, int level,
                                     const gcode::SourceLocation& where) {
    if (!pressStartWhenAwaited_ || key.function->parameter != param::kExternStartInput ||
        level == key.activeLevel) {
        return;
    }
    if (sensorWatch_.read(pin, level, machine_.time(), where, 1e300) != SensorWatch::Verdict::WaitBegins) {
        return;
    }
    machine_.pulseInput(pin, key.activeLevel, kKeyPress);
    status_.postMessage("外部启动 extern START (" + params::inputName(pin) + ") pressed at " + program_.fileName(where) + ":" +
                std::to_string(where.line) + " (run without an operator)");
}

// The operator presses the extern START key, as the virtual-tool prompt asks.
void Controller::pressExternStart() {
    if (auto key = params::wiredInput(config_.parameters, param::kExternStartInput)) {
        machine_.pulseInput(key->pin, key->activeLevel, kKeyPress);
    }
}

std::optional<Controller::SensorWait> Controller::sensorWait() const {
    auto wait = sensorWatch_.current();
    if (!wait || state_ != RunState::Running) {
        return std::nullopt;
    }
    SensorWait out;
    out.input = magazine_.describeInput(wait->pin);
    out.awaitedLevel = 1 - wait->level;
    out.seconds = machine_.time() - wait->since;
    out.file = program_.fileName(wait->where);
    out.line = wait->where.line;
    return out;
}

} // namespace m350::controller
