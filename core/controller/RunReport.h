#pragma once

#include "core/common/Alarm.h"
#include "core/devices/Magazine.h"
#include "core/gcode/Diagnostic.h"
#include "core/machine/MachineTypes.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace m350::controller {

enum class RunStatus { Ok, Alarm, Error };

// What a run leaves behind, as `m350-sim` reports it.
struct RunReport {
    RunStatus status = RunStatus::Ok;
    std::optional<Alarm> alarm;
    std::vector<gcode::Diagnostic> diagnostics;
    machine::Axes machine = machine::Axes::Zero();
    machine::Axes work = machine::Axes::Zero();
    int tool = 0;
    // A stop in a tool change left the spindle's tool in doubt (ToolDoubt::notice()): what the
    // controller says until the operator enters the tool.
    std::optional<Alarm> toolUnsure;
    // What the controller warned of (StatusBoard::warn): a tool used without a length ...
    std::vector<Alarm> warnings;
    std::map<int, int> pockets; // pocket -> tool (0 = empty)
    // Tools the spindle let fall onto the table (a drawbar released with no pocket under the tool,
    // as a stop mid-change can leave it), in the order they fell: in neither the spindle nor a pocket.
    std::vector<devices::FallenTool> fallenTools;
    std::array<int, machine::kOutputCount> outputs{};
    std::vector<std::string> messages; // bounded (MessageLog): the first and the last
    std::uint64_t messagesOmitted = 0;  // left out between them
    std::vector<Message> messageWords;  // the same by message id (an empty id: the program's own words)
    double simTime = 0.0;
    std::uint64_t blocks = 0;
};

} // namespace m350::controller
