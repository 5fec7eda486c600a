#include "core/controller/Homing.h"

#include "core/controller/RunView.h"
#include "core/params/IoPorts.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>

namespace m350::controller {


namespace {

constexpr double kBackOff = 2.0; // mm the axis leaves the switch by between approaches
constexpr std::array<int, machine::kAxisCount> kHomingOrder{2, 0, 1, 3, 4}; // Z first, clear of the work

} // namespace

Homing::Homing(machine::SimulatedMachine& machine, const params::ParameterTable& parameters, const std::string& folder,
               RunView& run)
    : machine_(machine), parameters_(parameters),
      parametersFile_(folder.empty() ? std::string("params.toml") : folder + "/params.toml"), run_(run) {}

bool Homing::homeSwitchWired(int axis) const {
    return params::wiredInput(parameters_, param::kHomeSwitchX + 3 * axis).has_value();
}

std::vector<int> Homing::homeableAxes() const {
    std::vector<int> axes{0, 1, 2};
    for (int axis = 3; axis < machine::kAxisCount; ++axis) {
        if (homeSwitchWired(axis)) {
            axes.push_back(axis);
        }
    }
    return axes;
}

bool Homing::needsBootHomingPrompt() const {
    return parameters_.get(param::kHomeAfterBooting) == 0.0 && !xyzHomed();
}

std::optional<Alarm> Homing::home(const std::vector<int>& axes) {
    const double startedAt = machine_.time();
    for (int axis : kHomingOrder) {
        if (std::find(axes.begin(), axes.end(), axis) == axes.end()) {
            continue;
        }
        if (auto alarm = homeAxis(axis, startedAt)) {
            run_.raiseAlarm(*alarm);
            return alarm;
        }
    }
    return std::nullopt;
}

// The home switches of the simulated world: before the first homing each lies the machine folder's
// switch distance ([homing] switch_distance) away in the homing direction; a machine that starts
// homed stands kBackOff off them, where homing leaves it. A macro that homes by G31 or by reading
// the switch while it moves (a factory O501) finds them there too.
void Homing::startUp(bool homed, const std::array<double, machine::kAxisCount>& switchDistance) {
    homed_.fill(homed ? 1 : 0);
    const machine::Axes position = machine_.position();
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        machine::HomeSwitch homeSwitch = machine_.homeSwitch(axis);
        homeSwitch.side = parameters_.get(param::kHomingDirectionX + axis) != 0.0 ? 1.0 : -1.0;
        const double away = homed ? kBackOff : switchDistance[static_cast<std::size_t>(axis)];
        homeSwitch.at = position(axis) + homeSwitch.side * away;
        machine_.setHomeSwitch(axis, homeSwitch);
    }
}

std::optional<Alarm> Homing::homeAxis(int axis, double since) {
    const params::ParameterTable& p = parameters_;
    const char name = machine::kAxisNames[static_cast<std::size_t>(axis)];
    if (!homeSwitchWired(axis)) {
        int first = param::kHomeSwitchX + 3 * axis;
        return Alarm::of(AlarmCode::NotHomed,
                         message("no_home_switch", {std::string(1, name), std::to_string(first), std::to_string(first + 2)}),
                         parametersFile_);
    }
    const params::PortAssignment homeSwitch = *params::wiredInput(p, param::kHomeSwitchX + 3 * axis);
    const int pin = homeSwitch.pin;
    const int active = homeSwitch.activeLevel;
    const double direction = p.get(param::kHomingDirectionX + axis) != 0.0 ? 1.0 : -1.0;
    const double speed = p.get(param::kHomingSpeedX + axis) > 0 ? p.get(param::kHomingSpeedX + axis) : 500.0;
    const double slow = p.get(param::kHomingSecondSpeed) > 0 ? p.get(param::kHomingSecondSpeed) : speed / 10.0;
    const int cycles = std::max(1, saturatingInt(p.get(param::kHomingCycles)));
    const double home = p.get(param::kHomePositionX + axis);
    homed_[static_cast<std::size_t>(axis)] = 0; // searching: no trusted position until the switch

    // the switch is where the simulated world has it (placeHomeSwitches); from beyond it the
    // approach starts at once
    machine::Axes position = machine_.position();
    const double distance = std::max(0.0, (machine_.homeSwitch(axis).at - position(axis)) * direction);
    auto moveBy = [&](double delta, double feed) {
        position(axis) += delta;
        machine_.feed(position, feed);
    };
    moveBy(direction * distance, speed);
    machine_.setInput(pin, active);
    for (int cycle = 1; cycle < cycles; ++cycle) {
        if (run_.passedTimeLimit(since)) {
            // param 106 = 1e9 asked for hours of approaches: the runaway guard holds here too
            std::vector<std::string> numbers = run_.timeLimitNumbers(since);
            const char* id = numbers.size() > 1 ? "time_limit_homing_since" : "time_limit_homing";
            numbers.insert(numbers.begin(), std::string(1, name));
            numbers.push_back(std::to_string(cycle));
            numbers.push_back(std::to_string(cycles));
            return Alarm::of(AlarmCode::SimulatedTimeLimit, message(id, numbers), parametersFile_);
        }
        moveBy(-direction * kBackOff, slow);
        machine_.setInput(pin, 1 - active);
        moveBy(direction * kBackOff, slow);
        machine_.setInput(pin, active);
    }
    moveBy(-direction * kBackOff, slow);
    machine_.setInput(pin, 1 - active);
    position(axis) = home;
    machine_.setPosition(position);
    homed_[static_cast<std::size_t>(axis)] = 1;
    return std::nullopt;
}

} // namespace m350::controller
