#include "core/controller/ToolTableSave.h"

#include "core/controller/Controller.h"
#include "core/params/ParameterNumbers.h"

#include <map>

namespace m350::controller {

namespace {

// What the machine folder keeps beside tool.tbl: on the M350 the tools' Z parameters 930-945 and
// 973-992 as they are now (params.toml lists them too, so both files agree), on a FANUC none.
std::map<int, double> toolZParameters(const Controller& controller) {
    std::map<int, double> zParameters;
    if (controller.dialect().id != gcode::DialectId::M350) {
        return zParameters;
    }
    for (int i = 0; i < param::kToolZOffsetCount; ++i) {
        zParameters[param::kToolZOffsetFirst + i] = controller.parameter(param::kToolZOffsetFirst + i);
    }
    for (int i = 0; i < param::kVirtualToolZOffsetCount; ++i) {
        zParameters[param::kVirtualToolZOffsetFirst + i] = controller.parameter(param::kVirtualToolZOffsetFirst + i);
    }
    return zParameters;
}

} // namespace

std::optional<Message> saveToolTable(Controller& controller, const config::MachineFolder& folder,
                                         const files::AtomicWriteHooks& hooks) {
    ToolTableEdits& edits = controller.toolTableEdits();
    const tools::ToolData::Mark mark = edits.mark();
    if (auto error = folder.saveToolTable(edits.table(), toolZParameters(controller), hooks)) {
        return error;
    }
    edits.markSaved(mark);
    return std::nullopt;
}

std::optional<Message> saveParameters(Controller& controller, const config::MachineFolder& folder,
                                          const std::map<int, double>& values, const files::AtomicWriteHooks& hooks) {
    ToolTableEdits& edits = controller.toolTableEdits();
    if (!edits.changed()) {
        return folder.saveParameters(values);
    }
    const tools::ToolData::Mark mark = edits.mark();
    if (auto error = folder.saveToolTable(edits.table(), toolZParameters(controller), hooks, values)) {
        return error;
    }
    edits.markSaved(mark);
    return std::nullopt;
}

} // namespace m350::controller
