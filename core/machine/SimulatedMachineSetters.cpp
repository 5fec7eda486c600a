// The tool setters and home switches of the simulated world, and G31 against them.
#include "core/machine/SimulatedMachine.h"

#include <algorithm>
#include <cmath>

namespace m350::machine {

namespace {

// A range of fractions along a move, [from, to]; empty when from > to.
struct Span {
    double from = 0.0;
    double to = 1.0;
    bool empty() const { return from > to + 1e-12; } // a tool resting exactly on the top touches it
    Span within(const Span& other) const { return {std::max(from, other.from), std::min(to, other.to)}; }
};

constexpr Span kNone{1.0, 0.0};

// Where along p0 + (p1 - p0) f a value v(f) = v0 + dv f stays at or below `limit`.
Span atOrBelow(double v0, double dv, double limit) {
    if (std::abs(dv) < 1e-12) {
        return v0 <= limit + 1e-9 ? Span{0.0, 1.0} : kNone;
    }
    double f = (limit - v0) / dv;
    return dv < 0.0 ? Span{f, 1.0} : Span{0.0, f};
}

// Where the XY path comes within `reach` of (cx, cy): a quadratic in f.
Span withinReach(const Axes& from, const Axes& to, double cx, double cy, double reach) {
    const double px = from(0) - cx, py = from(1) - cy;
    const double dx = to(0) - from(0), dy = to(1) - from(1);
    const double a = dx * dx + dy * dy;
    const double c = px * px + py * py - reach * reach;
    if (a < 1e-18) {
        return c <= 1e-9 ? Span{0.0, 1.0} : kNone;
    }
    const double b = 2.0 * (dx * px + dy * py);
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) {
        return kNone;
    }
    const double root = std::sqrt(discriminant);
    return {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)};
}

} // namespace

bool SimulatedMachine::setterPressed(const ToolSetter& setter, const Axes& at) const {
    double dx = at(0) - setter.x;
    double dy = at(1) - setter.y;
    double reach = setter.radius + toolRadius_;
    bool under = &setter == &floatingSetter_ || dx * dx + dy * dy <= reach * reach + 1e-9;
    return setter.port != 0 && under && at(2) <= setter.top + toolLength_ + 1e-9;
}

double SimulatedMachine::setterPenetration(const Axes& from, const Axes& to) const {
    if (setter_.port == 0) {
        return 0.0;
    }
    const double trip = setter_.top + toolLength_; // the spindle Z where the tip meets the top
    const Span over = withinReach(from, to, setter_.x, setter_.y, setter_.radius + toolRadius_).within({0.0, 1.0});
    if (over.empty()) {
        return 0.0;
    }
    // Z is linear along the move: the deepest point over the setter is at one end of the span
    const double dz = to(2) - from(2);
    const double deepest = trip - std::min(from(2) + dz * over.from, from(2) + dz * over.to);
    const double already = setterPressed(setter_, from) ? trip - from(2) : 0.0;
    return std::max(0.0, deepest - std::max(already, 0.0));
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

// Where along the straight move from here to `target` (0..1) the setter's switch comes to `level`.
// It is pressed while the tool tip is at or below the setter's top and the tool's side within the
// stylus (a disc stylus is touched from above and from the side, as a TS27R's is); the switch
// opens where the move leaves that region.
std::optional<double> SimulatedMachine::setterCrossing(const ToolSetter& setter, const Axes& target, int level) const {
    const bool pressing = level == setter.activeLevel;
    Span contact = atOrBelow(position_(2), target(2) - position_(2), setter.top + toolLength_).within({0.0, 1.0});
    if (&setter != &floatingSetter_) {
        contact = contact.within(withinReach(position_, target, setter.x, setter.y, setter.radius + toolRadius_));
    }
    if (contact.empty()) {
        return std::nullopt;
    }
    if (pressing) {
        return std::clamp(contact.from, 0.0, 1.0);
    }
    if (contact.from > 1e-9 || setterPressed(setter, target)) {
        return std::nullopt; // not pressed where it starts, or still pressed where it ends
    }
    return std::clamp(contact.to, 0.0, 1.0);
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
