#pragma once

#include "core/common/Alarm.h"
#include "core/common/Numeric.h"
#include "core/controller/MagazineDriver.h"
#include "core/controller/ToolDoubt.h"
#include "core/controller/TraceWriter.h"
#include "core/macro/BlockSink.h"
#include "core/macro/Value.h"

#include <functional>
#include <memory>
#include <optional>
#include <set>

namespace m350::gcode {
struct Dialect;
}

namespace m350::params {
class ParameterTable;
}

namespace m350::macro {
class Executor;
}

namespace m350::controller {

// What the controller checks of the tool a block names and the tool the spindle turns: a T the
// magazine cannot serve is refused at its word; after a stop inside a tool change the spindle's
// tool is in doubt (ToolDoubt) and the next change is refused until the operator says; a tool that
// turns with no length set is warned of, once per tool. It keeps the last T word, the doubt and the
// tools already warned of; the Controller posts what it returns.
class SpindleToolGuard {
public:
    // What the guard reads; all of it belongs to the Controller and outlives it.
    struct Context {
        const gcode::Dialect& dialect;
        const params::ParameterTable& parameters;
        const MagazineDriver& magazine;
        const std::unique_ptr<macro::Executor>& executor; // made anew for each program
        std::function<macro::Value(int)> variable;        // a variable as a macro reads it (#1504)
    };
    explicit SpindleToolGuard(Context context);

    // A block on its way to the machine (macro::MachineAccess::manageTools), before tool life takes
    // its words: its T is noted (a FANUC's change fetches that tool at M06); while in doubt a change
    // (an M350's T, a FANUC's M06) is refused at its word with a MacroError, unless the tool change
    // program itself runs the block. Asked for every block: inline.
    void checkBlock(const macro::EvaluatedBlock& block) {
        if (block.has('T')) [[unlikely]] {
            lastToolWord_ = roundToInt(block.words[block.firstOf['T' - 'A']].value);
        }
        if (doubt_.doubt()) [[unlikely]] {
            refuseChangeInDoubt(block);
        }
    }
    // A block tool life did not take: on a machine with a magazine device, a T the magazine cannot
    // serve, or an M61, is refused at its word with a MacroError.
    void checkToolWord(const macro::EvaluatedBlock& block) const {
        if (context_.magazine.device() && (block.has('T') || block.mCodes.has(61))) [[unlikely]] {
            refuseToolWord(block);
        }
    }
    // The last T a block gave, 0 before any.
    int lastToolWord() const { return lastToolWord_; }

    // A RESET, an E-stop or an alarm stopped the run inside a tool change: the change was fetching
    // #1504 (M350) or the last T word (FANUC), with param 800 or `pmcSpindleTool` on record. The
    // notice to post when this starts a doubt; nullopt while one stands (the E-stop, then its RESET).
    std::optional<Alarm> stoppedInChange(int pmcSpindleTool);
    // The operator entered the tool the spindle holds.
    void confirmed() { doubt_.confirmed(); }
    const ToolDoubt& doubt() const { return doubt_; }

    // Whether the spindle turning `tool` was looked at already (the last tool toolTurns() saw).
    // Asked after every step: inline.
    bool lengthLookedAt(int tool) const { return tool == lengthLookedAt_; }
    // The spindle turns `tool` (the block at `where`). On the M350 with its fixed setter on
    // (param 130) every tool is set (对刀) before it cuts: a tool whose Z offset (params 930-945,
    // a virtual tool's 973-992) is 0 gives the warning "tool_length_unset", once per tool.
    std::optional<Alarm> toolTurns(int tool, const TraceSource& where);

private:
    void refuseChangeInDoubt(const macro::EvaluatedBlock& block) const;
    void refuseToolWord(const macro::EvaluatedBlock& block) const;
    bool changingTool() const;

    Context context_;
    ToolDoubt doubt_;
    int lastToolWord_ = 0;
    int lengthLookedAt_ = 0;     // the spindle tool toolTurns() last saw turning
    std::set<int> lengthWarned_; // the tools a missing length was warned of, once each
};

} // namespace m350::controller
