#pragma once

#include "core/interp/ModalInterpreter.h"
#include "core/tools/ToolData.h"

namespace m350::controller {

// The spindle's tool on a machine whose magazine no device drives: a FANUC machine's M06 (the
// operator's change by hand) names it, and the PMC keeps it where M85 reads and writes it;
// LinuxCNC's M61 sets it, and LinuxCNC's random changer puts the old tool into the new one's
// pocket at M06. With a magazine device the device knows what the spindle holds.
class SpindleToolByHand {
public:
    SpindleToolByHand(tools::ToolData& tools, bool randomChanger) : tools_(tools), randomChanger_(randomChanger) {}

    int tool() const { return tool_; }
    void set(int tool) { tool_ = tool; }
    int& pmcRegister() { return tool_; } // where the magazine wiring's M85 stores it
    void take(const interp::ModalInterpreter::ToolChange& change);

private:
    tools::ToolData& tools_;
    bool randomChanger_;
    int tool_ = 0;
};

} // namespace m350::controller
