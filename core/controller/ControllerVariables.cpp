// The variables that belong to the machine: what macros read and write through #-numbers
// beyond their own storage.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"
#include "core/macro/Evaluator.h"

#include "core/params/AxisSetup.h"
#include "core/params/ParameterNumbers.h"

#include <cmath>

namespace m350::controller {

using macro::Value;
using macro::VariableInfo;
using macro::VariableKind;

namespace {

constexpr double kClearMessage = 1000; // `#1503 = 1000` clears the status line

} // namespace

Value Controller::variable(int number) {
    VariableInfo info = store_.map().describe(number);
    if (info.kind == VariableKind::Undefined) {
        return Value::empty();
    }
    return macro::VariableStore::ownsKind(info.kind) ? store_.read(info, number) : readSystem(info, number);
}

Value Controller::readSystem(const VariableInfo& info, int number) {
    const int axis = info.index & 7;
    switch (info.kind) {
    case VariableKind::WorkOffset: return Value::of(offsets_.get(info.index >> 3, axis));
    case VariableKind::MachinePosition: return Value::of(scan_.position()(info.index));
    case VariableKind::WorkPosition: {
        if (info.index < 0 || (info.index >> 3) == interp_.activeSlot()) {
            return Value::of(interp_.workPosition()(info.index < 0 ? info.index + 8 : axis));
        }
        double tool = axis == 2 ? interp_.toolZOffset() : 0.0;
        return Value::of(scan_.position()(axis) - offsets_.get(info.index >> 3, axis) - tool);
    }
    case VariableKind::BlockEnd: return Value::of(interp_.workPosition()(info.index));
    case VariableKind::SkipPosition: // FANUC #5061-#5065: where the skip signal came, work coordinates
        return Value::of(interp_.lastProbe().position(info.index) - interp_.workOffset()(info.index));
    case VariableKind::ProbeResult: { // M350 #1920-#1924 result per axis (2 hit), #1925-#1929 machine position
        const interp::ModalInterpreter::Probe& probe = interp_.lastProbe();
        if (info.index >= machine::kAxisCount) {
            return Value::of(probe.position(info.index - machine::kAxisCount));
        }
        return Value::of(probe.status[static_cast<std::size_t>(info.index)]);
    }
    case VariableKind::Input: {
        int level = machine_.input(info.index);
        panel_.readInput(info.index, level);
        return Value::of(level);
    }
    case VariableKind::Output: return Value::of(scan_.output(info.index));
    case VariableKind::Homed: return Value::of(homing_.homed(info.index) ? 1 : 0);
    case VariableKind::AxisCount: return Value::of(params::axisSetup(config_.parameters).count);
    case VariableKind::Dialog: return Value::of(panel_.dialogAnswer());
    case VariableKind::Message: return Value::of(0);
    case VariableKind::InterfaceInput: return interfacePmc_.input(info.index);
    case VariableKind::InterfaceInputs: return interfacePmc_.inputs();
    case VariableKind::InterfaceOutput: return interfacePmc_.output(info.index);
    case VariableKind::InterfaceOutputs: return interfacePmc_.outputs(info.index);
    case VariableKind::OperationControl: return Value::of(operation_.value(info.index));
    case VariableKind::ModalGroup: return Value::of(interp_.state().groups[static_cast<std::size_t>(info.index)]);
    case VariableKind::ModalWord: {
        const interp::ModalState& s = interp_.state();
        switch (info.index) {
        case 107: return Value::of(s.radiusOffset);
        case 109: return Value::of(s.feed);
        case 111: return Value::of(s.lengthOffset);
        case 113: return Value::of(s.lastM);
        case 119: return Value::of(s.spindleSpeed);
        case 120: return Value::of(s.selectedTool);
        case 130: return Value::of(s.additionalSystem); // G54.1 P (0 under G54-G59)
        default: return Value::empty();
        }
    }
    case VariableKind::ToolOffset: return Value::of(tools_.offsetVariable(info.index));
    case VariableKind::SpindleLoad: return Value::of(breakage_.spindleLoad().reg());
    case VariableKind::Alarm:
    case VariableKind::StopMessage: return Value::of(0);
    default: return Value::empty();
    }
    (void)number;
}

std::optional<Message> Controller::writeSystem(const VariableInfo& info, int number, double value,
                                               std::string_view text) {
    switch (info.kind) {
    case VariableKind::WorkOffset: offsets_.set(info.index >> 3, info.index & 7, value); return std::nullopt;
    case VariableKind::Output: scan_.setOutput(info.index, value != 0.0 ? 1 : 0); return std::nullopt;
    case VariableKind::ToolOffset: return tools_.setOffsetVariable(info.index, value);
    case VariableKind::Homed: homing_.setHomed(info.index, value != 0.0); return std::nullopt;
    case VariableKind::ProbeResult: interp_.setProbeStatus(info.index, value); return std::nullopt; // #1920-#1924
    case VariableKind::InterfaceOutput: return interfacePmc_.setOutput(info.index, value);
    case VariableKind::InterfaceOutputs: return interfacePmc_.setOutputs(info.index, value);
    case VariableKind::OperationControl: return setOperationControl(info.index, value);
    case VariableKind::MachinePosition: {
        // M350 #880-#884: the axis takes this machine position where it stands, without moving, and
        // is no longer homed (a dual-Y gantry's fndzero.nc copies Y to A so, then sets #1518 = 1)
        machine::Axes position = scan_.position();
        position(info.index) = value;
        scan_.setPosition(position);
        homing_.setHomed(info.index, false);
        return std::nullopt;
    }
    case VariableKind::Message:
        if (value == kClearMessage) {
            status_.clearStatus();
        } else if (!text.empty()) {
            status_.showStatus(std::string(text));
            status_.postMessage(std::string(text));
        }
        return std::nullopt;
    case VariableKind::Dialog: panel_.showDialog(value, text); return std::nullopt;
    case VariableKind::Alarm: {
        return macro::macroAlarmWords(value, text);
    }
    case VariableKind::StopMessage:
        status_.postMessage(message("notice_3006_continued", {std::string(text)}));
        return std::nullopt;
    default: return message("variable_not_writable", {store_.map().describeWords(number)});
    }
}

} // namespace m350::controller
