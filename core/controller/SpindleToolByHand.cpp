#include "core/controller/SpindleToolByHand.h"

namespace m350::controller {

void SpindleToolByHand::take(const interp::ModalInterpreter::ToolChange& change) {
    if (!change.byHand && randomChanger_) {
        tools_.swapPockets(tool_, change.tool);
    }
    tool_ = change.tool;
}

} // namespace m350::controller
