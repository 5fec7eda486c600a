// The controller's side of tool life management: the blocks' words and the cutting time.
#include "core/controller/ToolLifeCounter.h"

#include "core/gcode/Dialect.h"
#include "core/machine/ScanMachine.h"
#include "core/macro/Executor.h"

namespace m350::controller {

ToolLifeCounter::ToolLifeCounter(tools::LifeData data, const RunState& state,
                                 const std::unique_ptr<macro::Executor>& executor, const gcode::Dialect& dialect,
                                 const machine::ScanMachine& scan)
    : state_(state), executor_(executor), dialect_(dialect), scan_(scan) {
    life_.setData(std::move(data));
}

bool ToolLifeCounter::applyWords(macro::EvaluatedBlock& block) {
    return tools::applyToolLife(life_, block, {dialect_.tCodeProgram >= 0, scan_.scanning()});
}

// Only the feed moves and arcs of a program run cut: not rapids, dwells, manual moves, a hold (its
// cut short by RunControl), waits for an input (no move is made), or a tool change program's moves.
// The panel has no machine lock, Z lock, dry run or single block: when they come, their time must
// be left out here too (the FANUC 0i manual excludes it).
void ToolLifeCounter::countCuttingTime(const machine::MachineEvent& event) {
    using Type = machine::MachineEvent::Type;
    // Most programs run with no tool life group in use: nothing to count, no need to ask the executor.
    if (state_ == RunState::Running && (event.type == Type::Feed || event.type == Type::Arc) && life_.inUse() &&
        executor_ && !executor_->changingTool()) {
        life_.cut(event.start, event.end);
    }
}

bool ToolLifeCounter::resetGroup(int group, Message* why) {
    std::optional<Message> refusal;
    if (programActive(state_)) {
        refusal = message("tool_life_reset_running", {std::to_string(group)});
    } else {
        refusal = life_.resetGroup(group);
    }
    if (refusal && why) {
        *why = *refusal;
    }
    return !refusal;
}

} // namespace m350::controller
