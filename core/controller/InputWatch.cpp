#include "core/controller/InputWatch.h"

#include "core/machine/SimulatedMachine.h"
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

void InputWatch::read(int pin, int level, bool unattended) {
    auto where = context_.location();
    if (!where) {
        return;
    }
    auto function = params::inputOnPin(context_.parameters, pin);
    if (operatorInput(function)) {
        if (unattended) {
            pressStartIfAwaited(*function, pin, level, *where);
        }
        return;
    }
    machine::SimulatedMachine& machine = context_.machine;
    const double timeout = context_.settings.sensorTimeout;
    switch (sensors_.read(pin, level, machine.time(), *where, timeout)) {
    case SensorWatch::Verdict::Reading:
    case SensorWatch::Verdict::Waiting: return;
    case SensorWatch::Verdict::WaitBegins:
        if (context_.trace) {
            context_.trace->sensorWait(machine.time(), params::inputName(pin), 1 - level,
                                       {context_.program.fileName(*where), where->line});
        }
        return;
    case SensorWatch::Verdict::TimedOut: {
        Message what = message("sensor_timeout", {context_.describeInput(pin), std::to_string(1 - level), seconds(timeout),
                                                  context_.program.fileName(*where), std::to_string(where->line)});
        sensors_.clear();
        throw macro::MacroError::of(AlarmCode::SensorTimeout, what);
    }
    }
}

// A run without an operator (run()) presses the extern START key when a macro waits for it, as
// the operator would after doing what the prompt asked, and says so.
void InputWatch::pressStartIfAwaited(const params::PortAssignment& key, int pin, int level,
                                     const gcode::SourceLocation& where) {
    if (key.function->parameter != param::kExternStartInput || level == key.activeLevel) {
        return;
    }
    machine::SimulatedMachine& machine = context_.machine;
    if (sensors_.read(pin, level, machine.time(), where, 1e300) != SensorWatch::Verdict::WaitBegins) {
        return;
    }
    machine.pulseInput(pin, key.activeLevel, kKeyPress);
    context_.post(message("notice_extern_start", {params::inputName(pin), context_.program.fileName(where),
                                                  std::to_string(where.line)}));
}

void InputWatch::pressExternStart() {
    if (auto key = params::wiredInput(context_.parameters, param::kExternStartInput)) {
        context_.machine.pulseInput(key->pin, key->activeLevel, kKeyPress);
    }
}

std::optional<SensorWait> InputWatch::wait() const {
    auto wait = sensors_.current();
    if (!wait) {
        return std::nullopt;
    }
    SensorWait out;
    out.input = argumentIn(context_.describeInput(wait->pin), MessageLanguage::English);
    out.awaitedLevel = 1 - wait->level;
    out.seconds = context_.machine.time() - wait->since;
    out.file = context_.program.fileName(wait->where);
    out.line = wait->where.line;
    return out;
}

} // namespace m350::controller
