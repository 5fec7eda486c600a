#include "core/machine/ScanMachine.h"

#include "core/machine/ArcGeometry.h"

namespace m350::machine {

void ScanMachine::beginScan(const Axes& from) {
    scanning_ = true;
    refusal_.reset();
    position_ = from;
    spindle_ = machine_.spindleState();
    rpm_ = machine_.spindleRpm();
    coolant_ = machine_.coolantOn();
    outputs_.fill(std::nullopt);
}

void ScanMachine::rapid(const Axes& target) {
    scanning_ ? void(position_ = target) : machine_.rapid(target);
}

void ScanMachine::feed(const Axes& target, double feed) {
    scanning_ ? void(position_ = target) : machine_.feed(target, feed);
}

void ScanMachine::arc(const Arc& arc, double feed) {
    scanning_ ? void(position_ = arc.end) : machine_.arc(arc, feed);
}

// Where a probe stops depends on the world at that moment, which a scan does not reach.
ProbeResult ScanMachine::probe(const Axes& target, double feed, int port, int level) {
    if (!scanning_) {
        return machine_.probe(target, feed, port, level);
    }
    refusal_ = message("scan_g31");
    position_ = target;
    ProbeResult result;
    result.position = target;
    return result;
}

void ScanMachine::dwell(double seconds) {
    if (!scanning_) {
        machine_.dwell(seconds);
    }
}

void ScanMachine::blockTime(double seconds) {
    if (!scanning_) {
        machine_.blockTime(seconds);
    }
}

// The PMC plays devices (a FANUC carousel's M81-M85), whose state a scan cannot follow.
void ScanMachine::auxiliary(int code) {
    if (!scanning_) {
        machine_.auxiliary(code);
        return;
    }
    refusal_ = message("scan_pmc_m", {std::to_string(code)});
}

void ScanMachine::spindle(SpindleState state, double rpm) {
    if (!scanning_) {
        machine_.spindle(state, rpm);
        return;
    }
    spindle_ = state;
    rpm_ = state == SpindleState::Stop ? 0.0 : rpm;
}

void ScanMachine::coolant(bool on) {
    scanning_ ? void(coolant_ = on) : machine_.coolant(on);
}

void ScanMachine::setOutput(int port, int level) {
    if (!scanning_) {
        machine_.setOutput(port, level);
        return;
    }
    outputs_[static_cast<std::size_t>(port - 1)] = level;
}

int ScanMachine::output(int port) const {
    const std::optional<int>& scanned = outputs_[static_cast<std::size_t>(port - 1)];
    return scanning_ && scanned ? *scanned : machine_.output(port);
}

void ScanMachine::setPosition(const Axes& position) {
    scanning_ ? void(position_ = position) : machine_.setPosition(position);
}

} // namespace m350::machine
