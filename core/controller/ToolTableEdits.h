#pragma once

#include "core/config/MachineConfig.h"
#include "core/controller/RunState.h"
#include "core/tools/ToolData.h"

#include <functional>
#include <string>

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::interp {
class ModalInterpreter;
}

namespace m350::controller {

class MagazineDriver;

// The tool table as the panel edits it (one store, see tools::ToolData): on the M350 a tool's Z is
// its parameter 930-945 / 973-992, on a FANUC offset n is tool n's row. Edits are refused while a
// program runs or holds; `why` says why. A FANUC's active G43 length is not re-read (the next G43
// or H does), as in LinuxCNC.
class ToolTableEdits {
public:
    // What the edits work on; all of it belongs to the Controller and outlives them.
    struct Context {
        tools::ToolData& tools;
        const RunState& state;
        std::function<bool()> jogging; // a manual move is under way
        const config::MachineConfig& config;
        interp::ModalInterpreter& interp;
        const machine::SimulatedMachine& machine;
        const MagazineDriver& magazine;
    };
    explicit ToolTableEdits(Context context);

    tools::ToolTable table() const { return context_.tools.table(); }
    bool putTool(const tools::ToolEntry& entry, Message* why = nullptr);
    bool removeTool(int tool, Message* why = nullptr);
    bool replaceTable(const tools::ToolTable& table, Message* why = nullptr);
    // Touch off (LinuxCNC's "Touch Off" to the tool table): with tool n in the spindle and its tip on
    // a gauge or a cut surface whose work Z is `workZ` (in the program's unit), the tool's Z changes
    // so that the display reads `workZ` there: on the M350 its parameter 930+ (applied at once), on
    // a FANUC its row (G10 L10 P n Z`workZ`) followed by G43 H n. Refused with no tool, a tool the
    // M350 has no Z parameter for, while a program runs or holds or a manual move is under way.
    bool touchOffTool(double workZ, Message* why = nullptr);
    // Whether the tool data changed since the start or the last save (by an edit, G10, a macro
    // writing #1430 ...): what a panel saves after.
    bool changed() const { return !(context_.tools.mark() == savedMark_); }
    // The saver tells which data it wrote (the mark it read before writing).
    void markSaved(tools::ToolData::Mark saved) { savedMark_ = saved; }
    // Changes when the tool data does (for a view that redraws only then).
    tools::ToolData::Mark mark() const { return context_.tools.mark(); }

private:
    Context context_;
    tools::ToolData::Mark savedMark_; // where the tool data stood when tool.tbl was last written
};

} // namespace m350::controller
