// The tool table as the panel edits it: rows, an import, touch off.
#include "core/controller/ToolTableEdits.h"

#include "core/controller/MagazineDriver.h"
#include "core/interp/ModalInterpreter.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterNumbers.h"

#include <cmath>

namespace m350::controller {

namespace {

bool refuse(Message* why, Message reason) {
    if (why) {
        *why = std::move(reason);
    }
    return false;
}

} // namespace

ToolTableEdits::ToolTableEdits(Context context) : context_(std::move(context)), savedMark_(context_.tools.mark()) {}

bool ToolTableEdits::putTool(const tools::ToolEntry& entry, Message* why) {
    if (programActive(context_.state)) {
        return refuse(why, message("tool_edit_running"));
    }
    if (auto problem = context_.tools.put(entry)) {
        return refuse(why, *problem);
    }
    return true;
}

bool ToolTableEdits::removeTool(int tool, Message* why) {
    if (programActive(context_.state)) {
        return refuse(why, message("tool_edit_running"));
    }
    if (!context_.tools.remove(tool)) {
        return refuse(why, message("tool_edit_not_in_table", {std::to_string(tool)}));
    }
    return true;
}

bool ToolTableEdits::replaceTable(const tools::ToolTable& table, Message* why) {
    if (programActive(context_.state)) {
        return refuse(why, message("tool_edit_running"));
    }
    for (const tools::ToolEntry& entry : table.entries()) {
        if (auto problem = tools::invalidEntry(entry)) {
            return refuse(why, *problem);
        }
    }
    context_.tools.replace(table);
    return true;
}

bool ToolTableEdits::touchOffTool(double workZ, Message* why) {
    if (!std::isfinite(workZ)) {
        return refuse(why, message("touch_off_not_finite"));
    }
    if (programActive(context_.state)) {
        return refuse(why, message("tool_edit_running"));
    }
    if (context_.jogging()) {
        return refuse(why, message("touch_off_moving"));
    }
    // the tool whose offset the display applies: #1300 on the M350, the spindle's on a FANUC
    const bool m350 = context_.config.dialect->id == gcode::DialectId::M350;
    const int tool = m350 ? context_.interp.currentTool() : context_.magazine.spindleTool();
    if (tool == 0) {
        return refuse(why, message("touch_off_empty"));
    }
    const double machineZ = context_.machine.position()(2);
    if (m350) {
        if (!tools::m350ZParameter(tool, context_.config.parameters)) {
            return refuse(why, message("touch_off_no_parameter", {std::to_string(tool)}));
        }
        const double others = context_.interp.workOffset()(2) - context_.interp.toolZOffset();
        if (auto problem = context_.tools.setZ(tool, tools::roundedOffset(machineZ - others - workZ))) {
            return refuse(why, *problem);
        }
        return true;
    }
    const double unit = context_.interp.axisUnit(2);
    const double others = context_.interp.workOffset()(2) - context_.interp.toolLengthOffset();
    const double z = tools::roundedOffset((machineZ - others - workZ * unit) / unit);
    if (auto problem = context_.tools.setZ(tool, z)) {
        return refuse(why, *problem);
    }
    context_.interp.applyLengthOffset(tool);
    return true;
}

} // namespace m350::controller
