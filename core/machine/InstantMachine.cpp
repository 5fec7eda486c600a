#include "core/machine/InstantMachine.h"

namespace m350::machine {

void InstantMachine::notify(const MachineEvent& event) {
    if (observer_) {
        observer_->onMachineEvent(event);
    }
}

void InstantMachine::move(MachineEvent::Type type, const Axes& target, double feed) {
    MachineEvent event;
    event.type = type;
    event.from = position_;
    event.to = target;
    event.feed = feed;
    event.start = event.end = time_;
    position_ = target;
    notify(event);
}

void InstantMachine::rapid(const Axes& target) {
    move(MachineEvent::Type::Rapid, target, 0.0);
}

void InstantMachine::feed(const Axes& target, double feed) {
    move(MachineEvent::Type::Feed, target, feed);
}

void InstantMachine::arc(const Axes& target, const Axes&, Plane, bool, int, double feed) {
    move(MachineEvent::Type::Arc, target, feed);
}

void InstantMachine::dwell(double seconds) {
    MachineEvent event;
    event.type = MachineEvent::Type::Dwell;
    event.from = event.to = position_;
    event.start = time_;
    time_ += seconds;
    event.end = time_;
    notify(event);
}

void InstantMachine::spindle(SpindleState state, double rpm) {
    if (state == spindle_ && (state == SpindleState::Stop ? 0.0 : rpm) == rpm_) {
        return;
    }
    spindle_ = state;
    rpm_ = state == SpindleState::Stop ? 0.0 : rpm;
    MachineEvent event;
    event.type = MachineEvent::Type::Spindle;
    event.start = event.end = time_;
    event.spindle = state;
    event.rpm = rpm_;
    notify(event);
}

void InstantMachine::coolant(bool on) {
    if (on == coolant_) {
        return;
    }
    coolant_ = on;
    MachineEvent event;
    event.type = MachineEvent::Type::Coolant;
    event.start = event.end = time_;
    event.level = on ? 1 : 0;
    notify(event);
}

void InstantMachine::setOutput(int port, int level) {
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
}

int InstantMachine::input(int port) {
    auto index = static_cast<std::size_t>(port - 1);
    if (forced_[index]) {
        return *forced_[index];
    }
    for (const IoLink& link : links_) {
        if (link.input == port) {
            const OutputState& out = outputs_[static_cast<std::size_t>(link.output - 1)];
            int level = time_ >= out.changedAt + link.delay ? out.level : out.previous;
            return link.inverted ? 1 - level : level;
        }
    }
    return inputs_[index];
}

} // namespace m350::machine
