#pragma once

#include "core/machine/MachineInterface.h"

#include <array>
#include <optional>
#include <vector>

namespace m350::machine {

// An output wired to an input through an actuator that answers after a delay: the clamp cylinder
// (OUT01 -> IN11 "tool released"), a magazine slide ... A stand-in for the device models.
struct IoLink {
    int output = 0;
    int input = 0;
    double delay = 0.15; // seconds
    bool inverted = false;
};

// The minimal machine the language runs on until the motion model lands: moves complete at once,
// dwells and block times advance the virtual clock, IO links answer after their delay.
class InstantMachine : public MachineInterface {
public:
    explicit InstantMachine(MachineObserver* observer = nullptr) : observer_(observer) {}

    void addLink(const IoLink& link) { links_.push_back(link); }
    // Holds an input at a level for the whole run (`m350-sim --input IN11=0`), whatever drives it.
    void forceInput(int port, int level) { forced_[static_cast<std::size_t>(port - 1)] = level; }
    void setInput(int port, int level) { inputs_[static_cast<std::size_t>(port - 1)] = level; }

    void rapid(const Axes& target) override;
    void feed(const Axes& target, double feed) override;
    void arc(const Axes& target, const Axes& center, Plane plane, bool clockwise, int turns, double feed) override;
    void dwell(double seconds) override;
    void blockTime(double seconds) override { time_ += seconds; }

    void spindle(SpindleState state, double rpm) override;
    void coolant(bool on) override;

    void setOutput(int port, int level) override;
    int output(int port) const override { return outputs_[static_cast<std::size_t>(port - 1)].level; }
    int input(int port) override;

    Axes position() const override { return position_; }
    void setPosition(const Axes& position) override { position_ = position; }
    double time() const override { return time_; }
    SpindleState spindleState() const override { return spindle_; }
    double spindleRpm() const override { return rpm_; }
    bool coolantOn() const override { return coolant_; }

private:
    struct OutputState {
        int level = 0;
        int previous = 0;
        double changedAt = -1e300;
    };
    void move(MachineEvent::Type type, const Axes& target, double feed);
    void notify(const MachineEvent& event);

    MachineObserver* observer_;
    Axes position_ = Axes::Zero();
    double time_ = 0.0;
    std::array<OutputState, kOutputCount> outputs_{};
    std::array<int, kInputCount> inputs_{};
    std::array<std::optional<int>, kInputCount> forced_{};
    std::vector<IoLink> links_;
    SpindleState spindle_ = SpindleState::Stop;
    double rpm_ = 0.0;
    bool coolant_ = false;
};

} // namespace m350::machine
