// What the operator edits from the panel rather than a program: work positions (清零, 坐标管理,
// 分中), variables, the spindle's tool number and parameters (teach buttons, the IO page's
// polarity); and who may write a parameter from a macro.
#include "core/controller/Controller.h"

#include "core/params/ParameterLimits.h"
#include "core/params/ParameterNumbers.h"

#include <cmath>

namespace m350::controller {

void Controller::setWorkPosition(int axis, double value) {
    int slot = interp_.activeSlot();
    double others = interp_.workOffset()(axis) - offsets_.get(slot, axis);
    offsets_.set(slot, axis, machine_.position()(axis) - others - value);
}

bool Controller::setSpindleToolNumber(int tool) {
    if (tool < 0 || state_ == RunState::Running || state_ == RunState::Hold) {
        return false;
    }
    if (config_.dialect->id == gcode::DialectId::M350) {
        config_.parameters.set(param::kCurrentTool, tool);
    } else {
        handTool_.set(tool);
    }
    syncToolLength();
    toolGuard_.confirmed();
    return true;
}

bool Controller::setVariable(int number, double value, Message* why) {
    auto refuse = [why](Message reason) {
        if (why) {
            *why = std::move(reason);
        }
        return false;
    };
    if (!std::isfinite(value)) {
        return refuse(message("variable_not_finite", {std::to_string(number)}));
    }
    macro::VariableInfo info = store_.map().describe(number);
    if (info.kind == macro::VariableKind::Undefined) {
        return refuse(message("variable_no_such", {std::to_string(number)}));
    }
    if (info.readOnly) {
        return refuse(message("variable_edit_read_only", {store_.map().describeWords(number)}));
    }
    if (macro::VariableStore::ownsKind(info.kind)) {
        store_.write(info, number, macro::Value::of(value));
        return true;
    }
    if (auto error = writeSystem(info, number, value, {})) {
        return refuse(*error);
    }
    return true;
}

// Parameters as the panel reads and writes them.
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
