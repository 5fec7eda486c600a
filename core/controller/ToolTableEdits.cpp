// The tool table as the panel edits it: rows, an import, touch off, and what saving it writes.
#include "core/controller/Controller.h"

#include "core/params/ParameterNumbers.h"

#include <cmath>

namespace m350::controller {

namespace {

bool refuse(std::string* why, std::string reason) {
    if (why) {
        *why = std::move(reason);
    }
    return false;
}

constexpr const char* kRunning = "a program is running: the tool table changes once it has stopped (RESET)";

} // namespace

bool Controller::putTool(const tools::ToolEntry& entry, std::string* why) {
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        return refuse(why, kRunning);
    }
    if (auto problem = tools_.put(entry)) {
        return refuse(why, *problem);
    }
    return true;
}

bool Controller::removeTool(int tool, std::string* why) {
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        return refuse(why, kRunning);
    }
    if (!tools_.remove(tool)) {
        return refuse(why, "tool " + std::to_string(tool) + " is not in the tool table");
    }
    return true;
}

bool Controller::replaceToolTable(const tools::ToolTable& table, std::string* why) {
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        return refuse(why, kRunning);
    }
    for (const tools::ToolEntry& entry : table.entries()) {
        if (auto problem = tools::invalidEntry(entry)) {
            return refuse(why, *problem);
        }
    }
    tools_.replace(table);
    return true;
}

bool Controller::touchOffTool(double workZ, std::string* why) {
    if (!std::isfinite(workZ)) {
        return refuse(why, "touch off: the measured Z is not a finite number");
    }
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        return refuse(why, kRunning);
    }
    if (manual_.jogging()) {
        return refuse(why, "touch off: a manual move is under way; wait for the axes to stop");
    }
    // the tool whose offset the display applies: #1300 on the M350, the spindle's on a FANUC
    const bool m350 = config_.dialect->id == gcode::DialectId::M350;
    const int tool = m350 ? interp_.currentTool() : spindleTool();
    if (tool == 0) {
        return refuse(why, "touch off sets the length of the tool in the spindle, and it is empty: load a tool first");
    }
    const double machineZ = machine_.position()(2);
    if (m350) {
        if (!tools::m350ZParameter(tool, config_.parameters)) {
            return refuse(why, "tool " + std::to_string(tool) +
                                   " has no Z offset parameter on this M350 (params 930-945 for the magazine's tools, "
                                   "973-992 for 20 virtual tools above its capacity)");
        }
        const double others = interp_.workOffset()(2) - interp_.toolZOffset();
        if (auto problem = tools_.setZ(tool, tools::roundedOffset(machineZ - others - workZ))) {
            return refuse(why, *problem);
        }
        return true;
    }
    const double unit = interp_.axisUnit(2);
    const double others = interp_.workOffset()(2) - interp_.toolLengthOffset();
    if (auto problem = tools_.setZ(tool, tools::roundedOffset((machineZ - others - workZ * unit) / unit))) {
        return refuse(why, *problem);
    }
    interp_.applyLengthOffset(tool);
    return true;
}

std::map<int, double> Controller::toolZParameters() const {
    std::map<int, double> zParameters;
    if (config_.dialect->id != gcode::DialectId::M350) {
        return zParameters;
    }
    for (int i = 0; i < param::kToolZOffsetCount; ++i) {
        zParameters[param::kToolZOffsetFirst + i] = config_.parameters.get(param::kToolZOffsetFirst + i);
    }
    for (int i = 0; i < param::kVirtualToolZOffsetCount; ++i) {
        const int number = param::kVirtualToolZOffsetFirst + i;
        zParameters[number] = config_.parameters.get(number);
    }
    return zParameters;
}

} // namespace m350::controller
