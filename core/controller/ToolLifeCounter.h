#pragma once

#include "core/controller/RunState.h"
#include "core/machine/MachineTypes.h"
#include "core/tools/ToolLifeBlocks.h"
#include "core/tools/ToolLifeManager.h"

#include <memory>
#include <string>

namespace m350::gcode {
struct Dialect;
}

namespace m350::machine {
class ScanMachine;
}

namespace m350::macro {
class Executor;
}

namespace m350::controller {

// FANUC tool life management as the controller runs it (core/tools/ToolLifeManager.h): groups from
// the machine folder's toollife.txt or G10 L3; T<ignore+n> selects group n's tool, M06 (on the
// M350: the T word) starts counting, feed moves and arcs of a run count for a minutes group. The
// caller writes the data back (config::MachineFolder::saveToolLife) when manager().changed().
class ToolLifeCounter {
public:
    // `state` and `executor` are the controller's (the executor is made anew for each program).
    ToolLifeCounter(tools::LifeData data, const RunState& state, const std::unique_ptr<macro::Executor>& executor,
                    const gcode::Dialect& dialect, const machine::ScanMachine& scan);

    tools::ToolLifeManager& manager() { return life_; }
    const tools::ToolLifeManager& manager() const { return life_; }

    // The block's tool life words (macro::MachineAccess::manageTools): true when the block was
    // tool life data and nothing else is to be done with it. Most blocks have none: asked inline.
    bool applyBlock(macro::EvaluatedBlock& block) {
        return tools::mayConcernToolLife(life_, block) && applyWords(block);
    }
    // Counts the cutting time of one machine event, when it cuts.
    void countCuttingTime(const machine::MachineEvent& event);
    // The operator's tool life reset of a group (its tools' used life to 0). Refused (false, with
    // the reason) while a program runs or holds, or for a group that is not entered.
    bool resetGroup(int group, Message* why = nullptr);

private:
    bool applyWords(macro::EvaluatedBlock& block);

    tools::ToolLifeManager life_;
    const RunState& state_;
    const std::unique_ptr<macro::Executor>& executor_;
    const gcode::Dialect& dialect_;
    const machine::ScanMachine& scan_;
};

} // namespace m350::controller
