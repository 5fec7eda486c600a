// Parameters as the panel reads and writes them (teach buttons, the IO page's polarity).
#include "core/controller/Controller.h"
#include "core/params/ParameterLimits.h"

#include <cmath>

namespace m350::controller {

double Controller::parameter(int n) const {
    return params::ParameterTable::valid(n) ? config_.parameters.get(n) : 0.0;
}

bool Controller::setParameter(int n, double value) {
    if (!params::ParameterTable::valid(n) || !std::isfinite(value) || params::refusedParameterValue(n, value)) {
        return false;
    }
    writes_.note(n, ParameterWrites::Writer::Panel);
    config_.parameters.set(n, value);
    if (n == param::kCurrentTool && config_.dialect->id == gcode::DialectId::M350 && state_ != RunState::Running &&
        state_ != RunState::Hold) {
        toolGuard_.confirmed(); // the Param page's 当前刀具号 entry: the operator says which tool it is
    }
    configureMachine(); // the setters, the spindle sensor and the speeds follow at once
    return true;
}

// A macro writes #(n+500). The machine's own code (its libraries, a hook file, pause.nc or
// error.nc) writes what it writes; the operator's (MDI, mdi.nc, the program loaded) needs the level
// the Param page needs for n.
std::optional<Message> Controller::parameterWrite(int n, double value) {
    (void)value;
    const std::optional<gcode::SourceLocation> at = executor_ ? executor_->location() : std::nullopt;
    const gcode::SourceFile* file = at && at->file < program_.files.size() ? &program_.files[at->file] : nullptr;
    const bool library = file && (file->role == gcode::FileRole::GLibrary || file->role == gcode::FileRole::MLibrary ||
                                  file->role == gcode::FileRole::Library);
    const bool machineCode = inEventHook_ || library || (hook_ && *hook_ != config::Hook::Mdi);
    if (!machineCode) {
        if (auto refused = writes_.refusal(n)) {
            return refused;
        }
    }
    writes_.note(n, machineCode ? ParameterWrites::Writer::Machine : ParameterWrites::Writer::Program,
                 file ? file->name + ":" + std::to_string(at->line) : std::string());
    return std::nullopt;
}

} // namespace m350::controller
