// The controller's side of tool life management: the blocks' words and the cutting time.
#include "core/controller/Controller.h"

#include "core/tools/ToolLifeBlocks.h"

namespace m350::controller {

bool Controller::manageTools(macro::EvaluatedBlock& block) {
    const bool took = tools::mayConcernToolLife(toolLife_, block) &&
                      tools::applyToolLife(toolLife_, block, {dialect().tCodeProgram >= 0, scan_.scanning()});
    if (toolLife_.enabled()) {
        machine_.setObserver(this); // groups entered by G10 L3: cutting time counts from now on
    }
    return took;
}

// Only the feed moves and arcs of a program run cut: not rapids, dwells, manual moves, a hold (its
// cut short by RunControl), waits for an input (no move is made), or a tool change program's moves.
// The panel has no machine lock, Z lock, dry run or single block: when they come, their time must
// be left out here too (the FANUC 0i manual excludes it).
void Controller::countCuttingTime(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    // Most programs run with no tool life group in use: nothing to count, no need to ask the executor.
    if (state_ == RunState::Running && (event.type == Type::Feed || event.type == Type::Arc) && toolLife_.inUse() &&
        executor_ && !executor_->changingTool()) {
        toolLife_.cut(event.start, event.end);
    }
}

bool Controller::resetToolLife(int group, std::string* why) {
    std::optional<std::string> refusal;
    if (state_ == RunState::Running || state_ == RunState::Hold) {
        refusal = "a program runs: reset the tool life of group " + std::to_string(group) + " when it has stopped";
    } else {
        refusal = toolLife_.resetGroup(group);
    }
    if (refusal && why) {
        *why = *refusal;
    }
    return !refusal;
}

} // namespace m350::controller
