// The machine's IO in virtual time: outputs, inputs and what drives them (linked actuators,
// devices, the simulated world), read through the trainer's faults.
#include "core/machine/SimulatedMachine.h"

#include <algorithm>

namespace m350::machine {

namespace {

// An input changing to `level` at virtual time `at`, as observers see it.
MachineEvent inputEvent(int port, int level, double at) {
    MachineEvent event;
    event.type = MachineEvent::Type::Io;
    event.start = event.end = at;
    event.port = -port;
    event.level = level;
    return event;
}

} // namespace

// An input an IoLink drives changes after the link's delay; it is reported when the clock reaches
// that moment, so observers see every event in time order.
void SimulatedMachine::reportLinkedInputs(double upTo) {
    while (!pendingInputs_.empty() && pendingInputs_.front().start <= upTo) {
        MachineEvent event = pendingInputs_.front();
        pendingInputs_.erase(pendingInputs_.begin());
        observer_->onMachineEvent(event);
    }
}

void SimulatedMachine::scheduleLinkedInputs(int output) {
    for (const IoLink& link : links_) {
        if (link.output != output) {
            continue;
        }
        // a later switch of the output cancels a change its input has not shown yet
        std::erase_if(pendingInputs_, [&link](const MachineEvent& e) { return e.port == -link.input; });
        if (faults_[static_cast<std::size_t>(link.input - 1)]) {
            continue; // a faulty sensor does not follow its actuator
        }
        const double at = time_ + link.delay;
        schedulePending(inputEvent(link.input, signalAt(link.input, at).level, at));
    }
}

void SimulatedMachine::schedulePending(MachineEvent event) {
    auto at = std::upper_bound(pendingInputs_.begin(), pendingInputs_.end(), event,
                               [](const MachineEvent& a, const MachineEvent& b) { return a.start < b.start; });
    pendingInputs_.insert(at, event);
}

void SimulatedMachine::driveInput(int port, int level, double at) {
    auto index = static_cast<std::size_t>(port - 1);
    auto& timeline = driven_[index];
    std::erase_if(timeline, [at](const std::pair<double, int>& change) { return change.first >= at; });
    // what is past matters only for the level now and the one before it
    while (timeline.size() > 2 && timeline[timeline.size() - 2].first <= time_) {
        timeline.erase(timeline.begin());
    }
    const int before = signalAt(port, at).level;
    timeline.emplace_back(at, level);
    if (!observer_) {
        return;
    }
    std::erase_if(pendingInputs_, [port, at](const MachineEvent& e) { return e.port == -port && e.start >= at; });
    if (faults_[index] || before == level) {
        return; // a faulty sensor does not follow its device; an unchanged one makes no event
    }
    schedulePending(inputEvent(port, level, at));
}

std::optional<SimulatedMachine::Signal> SimulatedMachine::drivenSignal(std::size_t index, double t) const {
    const auto& timeline = driven_[index];
    if (timeline.empty()) {
        return std::nullopt;
    }
    Signal s{inputs_[index], 1 - inputs_[index], inputChangedAt_[index]};
    for (const auto& [from, level] : timeline) {
        if (from > t) {
            break;
        }
        if (level != s.level) {
            s = Signal{level, s.level, from};
        }
    }
    return s;
}

void SimulatedMachine::setOutput(int port, int level) {
    OutputState& out = outputs_[static_cast<std::size_t>(port - 1)];
    if (out.level == level) {
        return;
    }
    out.previous = out.level;
    out.level = level;
    out.changedAt = time_;
    MachineEvent event;
    event.type = MachineEvent::Type::Io;
    event.start = event.end = time_;
    event.port = port;
    event.level = level;
    notify(event);
    if (observer_) {
        scheduleLinkedInputs(port);
    }
}

void SimulatedMachine::setInput(int port, int level) {
    int& current = inputs_[static_cast<std::size_t>(port - 1)];
    if (current == level) {
        return;
    }
    current = level;
    inputChangedAt_[static_cast<std::size_t>(port - 1)] = time_;
    notify(inputEvent(port, level, time_));
}

SimulatedMachine::Signal SimulatedMachine::signalAt(int port, double t) const {
    auto index = static_cast<std::size_t>(port - 1);
    if (const Pulse& pulse = pulses_[index]; t >= pulse.from && t < pulse.until) {
        return {pulse.level, 1 - pulse.level, pulse.from};
    }
    if (const ToolSetter* setter = setterOn(port)) {
        int level = setterPressed(*setter, positionAt(t)) ? setter->activeLevel : 1 - setter->activeLevel;
        return {level, 1 - level, -1e300};
    }
    if (auto axis = homeSwitchAxisOn(port)) {
        const HomeSwitch& s = homeSwitches_[static_cast<std::size_t>(*axis)];
        int level = s.pressedAt(positionAt(t)(*axis)) ? s.activeLevel : 1 - s.activeLevel;
        return {level, 1 - level, -1e300};
    }
    if (auto driven = drivenSignal(index, t)) {
        return *driven;
    }
    if (spindleSensor_.port == port) {
        bool stopped = spindle_ == SpindleState::Stop && t >= spindleStopsAt_;
        int level = stopped ? spindleSensor_.activeLevel : 1 - spindleSensor_.activeLevel;
        return {level, 1 - level, stopped ? spindleStopsAt_ : -1e300};
    }
    for (const IoLink& link : links_) {
        if (link.input == port) {
            const OutputState& out = outputs_[static_cast<std::size_t>(link.output - 1)];
            bool arrived = t >= out.changedAt + link.delay;
            int level = arrived ? out.level : out.previous;
            int previous = arrived ? out.previous : out.level;
            if (link.inverted) {
                level = 1 - level;
                previous = 1 - previous;
            }
            return {level, previous, arrived ? out.changedAt + link.delay : -1e300};
        }
    }
    return {inputs_[index], 1 - inputs_[index], inputChangedAt_[index]};
}

int SimulatedMachine::input(int port) {
    const auto& fault = faults_[static_cast<std::size_t>(port - 1)];
    if (!fault) {
        return signalAt(port, time_).level;
    }
    switch (fault->kind) {
    case InputFault::Kind::Stuck: return fault->level;
    case InputFault::Kind::Delayed: return signalAt(port, time_ - fault->seconds).level;
    case InputFault::Kind::Bouncing: {
        Signal s = signalAt(port, time_);
        double since = time_ - s.changedAt;
        if (since >= fault->seconds || fault->period <= 0.0) {
            return s.level;
        }
        auto bounce = static_cast<long long>(since / fault->period);
        return bounce % 2 == 0 ? s.level : s.previous;
    }
    }
    return signalAt(port, time_).level;
}

} // namespace m350::machine
