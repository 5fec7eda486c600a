// The tool table as the panel edits it: rows, an import, touch off.
#include "core/controller/ToolTableEdits.h"

#include "core/controller/MagazineDriver.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
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

ToolTableEdits::ToolTableEdits(Context context) : context_(std::move(context)), savedMark_(context_.tools.mark()) {}

bool ToolTableEdits::putTool(const tools::ToolEntry& entry, std::string* why) {
    if (programActive(context_.state)) {
        return refuse(why, kRunning);
    }
    if (auto problem = context_.tools.put(entry)) {
        return refuse(why, problem->english());
    }
    return true;
}

bool ToolTableEdits::removeTool(int tool, std::string* why) {
    if (programActive(context_.state)) {
        return refuse(why, kRunning);
    }
    if (!context_.tools.remove(tool)) {
        return refuse(why, "tool " + std::to_string(tool) + " is not in the tool table");
    }
    return true;
}

bool ToolTableEdits::replaceTable(const tools::ToolTable& table, std::string* why) {
    if (programActive(context_.state)) {
        return refuse(why, kRunning);
    }
    for (const tools::ToolEntry& entry : table.entries()) {
        if (auto problem = tools::invalidEntry(entry)) {
            return refuse(why, problem->english());
        }
    }
    context_.tools.replace(table);
    return true;
}

bool ToolTableEdits::touchOffTool(double workZ, std::string* why) {
    if (!std::isfinite(workZ)) {
        return refuse(why, "touch off: the measured Z is not a finite number");
    }
    if (programActive(context_.state)) {
        return refuse(why, kRunning);
    }
    if (context_.jogging()) {
        return refuse(why, "touch off: a manual move is under way; wait for the axes to stop");
    }
    // the tool whose offset the display applies: #1300 on the M350, the spindle's on a FANUC
    const bool m350 = context_.config.dialect->id == gcode::DialectId::M350;
    const int tool = m350 ? context_.interp.currentTool() : context_.magazine.spindleTool();
    if (tool == 0) {
        return refuse(why, "touch off sets the length of the tool in the spindle, and it is empty: load a tool first");
    }
    const double machineZ = context_.machine.position()(2);
    if (m350) {
        if (!tools::m350ZParameter(tool, context_.config.parameters)) {
            return refuse(why, "tool " + std::to_string(tool) +
                                   " has no Z offset parameter on this M350 (params 930-945 for the magazine's tools, "
                                   "973-992 for 20 virtual tools above its capacity)");
        }
        const double others = context_.interp.workOffset()(2) - context_.interp.toolZOffset();
        if (auto problem = context_.tools.setZ(tool, tools::roundedOffset(machineZ - others - workZ))) {
            return refuse(why, problem->english());
        }
        return true;
    }
    const double unit = context_.interp.axisUnit(2);
    const double others = context_.interp.workOffset()(2) - context_.interp.toolLengthOffset();
    const double z = tools::roundedOffset((machineZ - others - workZ * unit) / unit);
    if (auto problem = context_.tools.setZ(tool, z)) {
        return refuse(why, problem->english());
    }
    context_.interp.applyLengthOffset(tool);
    return true;
}

} // namespace m350::controller
