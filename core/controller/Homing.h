#pragma once

#include "core/common/Alarm.h"
#include "core/machine/MachineTypes.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterTable.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace m350::controller {

class RunView;

// 回零 homing (the panel's key, `M98 P501 X` natively, the boot prompt) and which axes are homed.
// Each axis runs toward its home switch (an IO input, params 545-557), backs off and approaches
// again slowly, then takes the machine position of params 122-126.
class Homing {
public:
    static constexpr const char* kBootHomingPrompt = "是否进行开机寻零操作?";

    // `folder`: the machine folder, whose params.toml homing alarms name (their cause is a parameter).
    Homing(machine::SimulatedMachine& machine, const params::ParameterTable& parameters, const std::string& folder,
           RunView& run);

    // Homes the given axes (0 X .. 4 B), Z first. An alarm (raised on the run) when an axis has no
    // home switch.
    std::optional<Alarm> home(const std::vector<int>& axes);
    // One axis; `since`: the machine time --max-sim-time counts from (the homing's or the run's
    // start). The alarm is returned, not raised.
    std::optional<Alarm> homeAxis(int axis, double since);

    bool homed(int axis) const { return homed_[static_cast<std::size_t>(axis)] != 0; }
    bool xyzHomed() const { return homed(0) && homed(1) && homed(2); }
    void setHomed(int axis, bool homed) { homed_[static_cast<std::size_t>(axis)] = homed ? 1 : 0; }
    // #1515-#1519 as one array (1 homed), which the interpreter's soft limits read.
    const std::array<int, machine::kAxisCount>& flags() const { return homed_; }
    // Param 127 = 0 asks at boot whether to home (是否进行开机寻零操作?) while X, Y, Z are not homed.
    bool needsBootHomingPrompt() const;
    // X, Y and Z always; the 4th and 5th axes when their home switch is set.
    std::vector<int> homeableAxes() const;
    bool homeSwitchWired(int axis) const;
    // At start-up: every axis homed or none, and the simulated world's switches placed around
    // where the machine stands (`switchDistance`: the machine folder's [homing] switch_distance).
    void startUp(bool homed, const std::array<double, machine::kAxisCount>& switchDistance);

private:
    machine::SimulatedMachine& machine_;
    const params::ParameterTable& parameters_;
    std::string parametersFile_; // what homing alarms name
    RunView& run_;
    std::array<int, machine::kAxisCount> homed_{};
};

} // namespace m350::controller
