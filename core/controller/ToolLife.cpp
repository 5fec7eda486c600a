// The controller's side of tool life management: the blocks' words and the cutting time.
#include "core/controller/Controller.h"

#include "core/tools/ToolLifeBlocks.h"

namespace m350::controller {

bool Controller::manageTools(std::vector<macro::WordValue>& words) {
    bool took = tools::applyToolLife(toolLife_, words, {dialect().tCodeProgram >= 0, scan_.scanning()});
    if (toolLife_.enabled()) {
        machine_.setObserver(this); // groups entered by G10 L3: cutting time counts from now on
    }
    return took;
}

// Only the feed moves and arcs of a program run cut: not rapids, dwells, manual moves, or a hold.
void Controller::countCuttingTime(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    if (state_ == RunState::Running && (event.type == Type::Feed || event.type == Type::Arc)) {
        toolLife_.cut(event.start, event.end);
    }
}

} // namespace m350::controller
