#include "core/controller/ToolTableSave.h"

#include "core/controller/Controller.h"

namespace m350::controller {

std::optional<std::string> saveToolTable(Controller& controller, const config::MachineFolder& folder,
                                         const files::AtomicWriteHooks& hooks) {
    const tools::ToolData::Mark mark = controller.toolTableMark();
    if (auto error = folder.saveToolTable(controller.toolTable(), controller.toolZParameters(), hooks)) {
        return error;
    }
    controller.markToolTableSaved(mark);
    return std::nullopt;
}

} // namespace m350::controller
