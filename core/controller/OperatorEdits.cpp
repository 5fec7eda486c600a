// What the operator edits from the panel rather than a program: work positions (清零, 坐标管理,
// 分中), variables and the spindle's tool number.
#include "core/controller/Controller.h"

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
        fanucSpindleTool_ = tool;
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

} // namespace m350::controller
