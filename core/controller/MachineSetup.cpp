#include "core/controller/MachineSetup.h"

#include "core/machine/SimulatedMachine.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>

namespace m350::controller {

bool setUpMachine(machine::SimulatedMachine& simulated, const config::MachineConfig& config) {
    const params::ParameterTable& p = config.parameters;
    machine::MotionLimits limits;
    auto positive = [](double v, double fallback) { return v > 0.0 ? v : fallback; };
    limits.rapidSpeed = positive(p.get(param::kRapidSpeed), 10000.0) / 60.0;
    limits.maxSpeed = positive(p.get(param::kMaxSpeed), 12000.0) / 60.0;
    limits.feedAcceleration = positive(p.get(param::kFeedAcceleration), 500.0);
    limits.rapidAcceleration = positive(p.get(param::kRapidAcceleration), limits.feedAcceleration);
    limits.spindleStartDelay = std::max(0.0, p.get(param::kSpindleStartDelay));
    limits.spindleStopDelay = std::max(0.0, p.get(param::kSpindleStopDelay));
    limits.maxSpindleRpm = positive(p.get(param::kMaxSpindleRpm), 24000.0);
    simulated.setLimits(limits);
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        machine::HomeSwitch homeSwitch = simulated.homeSwitch(axis); // it stays where it is
        auto home = params::wiredInput(p, param::kHomeSwitchX + 3 * axis);
        homeSwitch.port = home ? home->pin : 0;
        homeSwitch.activeLevel = home ? home->activeLevel : 0;
        simulated.setHomeSwitch(axis, homeSwitch);
    }
    machine::ToolSetter setter;
    if (auto input = params::wiredInput(p, param::kFixedSetterInput)) {
        setter.port = input->pin;
        setter.activeLevel = input->activeLevel;
    }
    setter.x = p.get(param::kFixedSetterX);
    setter.y = p.get(param::kFixedSetterX + 1);
    setter.top = config.setterTop;
    setter.radius = config.setterRadius;
    simulated.setToolSetter(setter);
    machine::ToolSetter block; // the floating setter, where the machine folder puts one on the work
    if (auto input = params::wiredInput(p, param::kFloatingSetterInput); input && config.floatingSetterTop) {
        block.port = input->pin;
        block.activeLevel = input->activeLevel;
        block.top = *config.floatingSetterTop;
    }
    simulated.setFloatingSetter(block);
    if (auto stopped = params::wiredInput(p, param::kSpindleStoppedInput)) {
        simulated.setSpindleStoppedSensor({stopped->pin, stopped->activeLevel});
    }
    return setter.port != 0;
}

} // namespace m350::controller
