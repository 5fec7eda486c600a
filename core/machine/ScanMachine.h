#pragma once

#include "core/common/Message.h"
#include "core/machine/MachineInterface.h"

#include <array>
#include <optional>
#include <string>

namespace m350::machine {

// The interpreter's view of the machine: passes every call through to the real machine, except
// while scanning (断点加工 runs the blocks before its start line so): then motion only moves a
// shadow position, no time passes, the spindle, coolant and outputs change a shadow state, and
// nothing reaches the machine, its devices or its observers. Inputs still read the real machine.
// What cannot be scanned (G31, an M code for the PMC) is refused: refusal() says why.
class ScanMachine : public MachineInterface {
public:
    explicit ScanMachine(MachineInterface& machine) : machine_(machine) {}

    // Starts a scan from the real machine's state, the axes at `from`.
    void beginScan(const Axes& from);
    void endScan() { scanning_ = false; }
    bool scanning() const { return scanning_; }
    const std::optional<Message>& refusal() const { return refusal_; }
    // Something outside the machine the scanned blocks reached (a Modbus slave) that a scan cannot follow.
    void refuse(Message why) { refusal_ = std::move(why); }
    // The output levels the scanned blocks set (nullopt: not written).
    std::optional<int> scannedOutput(int port) const { return outputs_[static_cast<std::size_t>(port - 1)]; }

    void rapid(const Axes& target) override;
    void feed(const Axes& target, double feed) override;
    void arc(const Arc& arc, double feed) override;
    ProbeResult probe(const Axes& target, double feed, int port, int level) override;
    void dwell(double seconds) override;
    void blockTime(double seconds) override;
    void auxiliary(int code) override;
    void spindle(SpindleState state, double rpm) override;
    void coolant(bool on) override;
    void setOutput(int port, int level) override;
    int output(int port) const override;
    int input(int port) override { return machine_.input(port); }
    const Axes& position() const override { return scanning_ ? position_ : machine_.position(); }
    void setPosition(const Axes& position) override;
    double time() const override { return machine_.time(); }
    SpindleState spindleState() const override { return scanning_ ? spindle_ : machine_.spindleState(); }
    double spindleRpm() const override { return scanning_ ? rpm_ : machine_.spindleRpm(); }
    bool coolantOn() const override { return scanning_ ? coolant_ : machine_.coolantOn(); }

private:
    MachineInterface& machine_;
    bool scanning_ = false;
    std::optional<Message> refusal_;
    Axes position_ = Axes::Zero();
    SpindleState spindle_ = SpindleState::Stop;
    double rpm_ = 0.0;
    bool coolant_ = false;
    std::array<std::optional<int>, kOutputCount> outputs_{};
};

} // namespace m350::machine
