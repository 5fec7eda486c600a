#include "core/controller/StatusBoard.h"

#include "core/common/EchoText.h"
#include "core/gcode/Program.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/Executor.h"

#include <cmath>
#include <cstdio>

namespace m350::controller {

namespace {

// One modal group as the panel's modal line prints it: G00, G17, G80 ...
std::string gWord(double code) {
    char text[16];
    double whole = std::floor(code);
    if (code == whole) {
        std::snprintf(text, sizeof text, "G%02d", static_cast<int>(whole));
    } else {
        std::snprintf(text, sizeof text, "G%.1f", code);
    }
    return text;
}

} // namespace

StatusBoard::StatusBoard(const RunSettings& settings, const machine::SimulatedMachine& machine,
                         const interp::ModalInterpreter& interp, const std::unique_ptr<macro::Executor>& executor,
                         const gcode::Program& program)
    : machine_(machine), interp_(interp), executor_(executor), program_(program) {
    if (settings.trace) {
        trace_ = std::make_unique<TraceWriter>(*settings.trace, settings.traceLimit);
    }
}

TraceSource StatusBoard::source() const {
    if (executor_) {
        if (auto loc = executor_->location()) {
            return {program_.fileName(*loc), loc->line};
        }
    }
    return {};
}

void StatusBoard::postMessage(std::string text) {
    text = clipEcho(std::move(text));
    if (trace_) {
        trace_->message(machine_.time(), text, source());
    }
    messages_.add(std::move(text));
}

std::string StatusBoard::modalLine() const {
    const interp::ModalState& s = interp_.state();
    std::string line;
    for (int group : {1, 2, 3, 5, 6, 7, 8, 9}) {
        line += gWord(s.groups[static_cast<std::size_t>(group)]);
        line += ' ';
    }
    int slot = interp_.activeSlot();
    line += slot == 0 ? "G92" : gWord(53 + slot);
    char words[64];
    std::snprintf(words, sizeof words, " F%.0f S%.0f", s.feed, s.spindleSpeed);
    return line + words;
}

machine::SpindleState StatusBoard::spindleDisplay() const {
    machine::SpindleState state = machine_.spindleState();
    const int cycle = interp_.state().group(9);
    bool turning = state == machine::SpindleState::Forward || state == machine::SpindleState::Reverse;
    return turning && (cycle == 84 || cycle == 74) ? machine::SpindleState::Tap : state;
}

} // namespace m350::controller
