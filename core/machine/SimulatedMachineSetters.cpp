// The tool setters and home switches of the simulated world, and G31 against them.
#include "core/machine/SimulatedMachine.h"

#include <algorithm>

namespace m350::machine {

bool SimulatedMachine::setterPressed(const ToolSetter& setter, const Axes& at) const {
    double dx = at(0) - setter.x;
    double dy = at(1) - setter.y;
    bool under = &setter == &floatingSetter_ || dx * dx + dy * dy <= setter.radius * setter.radius;
    return setter.port != 0 && under && at(2) <= setter.top + toolLength_ + 1e-9;
}

// The setter whose switch is wired to `port`, if any.
const ToolSetter* SimulatedMachine::setterOn(int port) const {
    for (const ToolSetter* setter : {&setter_, &floatingSetter_}) {
        if (setter->port != 0 && setter->port == port) {
            return setter;
        }
    }
    return nullptr;
}

void SimulatedMachine::setPosition(const Axes& position) {
    for (int axis = 0; axis < kAxisCount; ++axis) {
        homeSwitches_[static_cast<std::size_t>(axis)].at += position(axis) - position_(axis);
    }
    position_ = position;
}

std::optional<int> SimulatedMachine::homeSwitchAxisOn(int port) const {
    for (int axis = 0; axis < kAxisCount; ++axis) {
        if (port != 0 && homeSwitches_[static_cast<std::size_t>(axis)].port == port) {
            return axis;
        }
    }
    return std::nullopt;
}

// Where along the move from here to `target` (0..1) the axis reaches its switch (pressing it) or
// leaves it (releasing it).
std::optional<double> SimulatedMachine::homeSwitchCrossing(int axis, const Axes& target, int level) const {
    const HomeSwitch& s = homeSwitches_[static_cast<std::size_t>(axis)];
    const double d = target(axis) - position_(axis);
    const bool pressing = level == s.activeLevel;
    if (pressing ? d * s.side <= 0.0 : d * s.side >= 0.0) {
        return std::nullopt;
    }
    constexpr double kRelease = 1e-6; // mm past the switch point, where it reads released
    const double fraction = (s.at - (pressing ? 0.0 : s.side * kRelease) - position_(axis)) / d;
    if (fraction < 0.0 || fraction > 1.0) {
        return std::nullopt;
    }
    return fraction;
}

// Where along the straight move from here to `target` (0..1) the setter's switch comes to `level`:
// pressed where Z comes down to the trip height over the setter, released where it rises above it.
std::optional<double> SimulatedMachine::setterCrossing(const ToolSetter& setter, const Axes& target, int level) const {
    const bool pressing = level == setter.activeLevel;
    const double dz = target(2) - position_(2);
    if (pressing ? dz >= 0.0 : dz <= 0.0) {
        return std::nullopt;
    }
    const double contact = setter.top + toolLength_;
    const double fraction = std::clamp((contact - position_(2)) / dz, 0.0, 1.0);
    const Axes at = position_ + (target - position_) * fraction;
    if (pressing ? !setterPressed(setter, at) : setterPressed(setter, target)) {
        return std::nullopt;
    }
    return fraction;
}

// The signal can come from a setter (where the tip meets its top, or leaves it) or be there from
// the start. A fault on the input acts as the control would suffer it: a stuck input never
// changes; a delayed one is heard late, so the axes run on by what the feed covers meanwhile, and
// a signal heard only after the move has ended is no signal.
ProbeResult SimulatedMachine::probe(const Axes& target, double feed, int port, int level) {
    ProbeResult result;
    if (input(port) == level) {
        result.triggered = true;
        result.position = position_;
        return result;
    }
    Axes stop = target;
    const std::optional<InputFault>& fault = faults_[static_cast<std::size_t>(port - 1)];
    const ToolSetter* setter = setterOn(port);
    const std::optional<int> homeAxis = homeSwitchAxisOn(port);
    const bool stuck = fault && fault->kind == InputFault::Kind::Stuck;
    std::optional<double> crossing;
    if (!stuck) {
        crossing = setter ? setterCrossing(*setter, target, level)
                          : homeAxis ? homeSwitchCrossing(*homeAxis, target, level) : std::nullopt;
    }
    if (crossing) {
        const double length = (target - position_).norm();
        const double lateness = fault && fault->kind == InputFault::Kind::Delayed ? fault->seconds : 0.0;
        const double along = *crossing * length + feed * feedOverride_ / 60.0 * lateness;
        if (along <= length + 1e-9) {
            stop = length > 0.0 ? Axes(position_ + (target - position_) * std::min(1.0, along / length)) : target;
            result.triggered = true;
        }
    }
    feed == 0.0 ? rapid(stop) : this->feed(stop, feed);
    result.position = position_;
    return result;
}

} // namespace m350::machine
