#pragma once

#include "core/machine/InputFault.h"
#include "core/machine/MachineInterface.h"
#include "core/machine/MotionLimits.h"
#include "core/machine/MotionProfile.h"

#include <array>
#include <deque>
#include <limits>
#include <optional>
#include <vector>

namespace m350::machine {

// An output wired to an input through an actuator that answers after a delay: the clamp cylinder
// (OUT01 -> IN11 "tool released"), a magazine slide ... until the device models take over.
struct IoLink {
    int output = 0;
    int input = 0;
    double delay = 0.15; // seconds
    bool inverted = false;
};

// The simulated machine in virtual time. Every move follows a trapezoidal velocity profile that is
// computed in closed form: issuing a move advances the clock by its duration at once, so a
// headless run jumps from event to event and a move of any length costs O(1). The last move is
// kept so positionAt() can show where the axes were at any moment of it.
class SimulatedMachine : public MachineInterface {
public:
    // The observer is told every event (and plays the PMC); none costs nothing per move.
    void setObserver(MachineObserver* observer) { observer_ = observer; }
    explicit SimulatedMachine(MachineObserver* observer = nullptr) : observer_(observer) {
        inputChangedAt_.fill(-1e300); // never changed
    }

    void setLimits(const MotionLimits& limits) { limits_ = limits; }
    const MotionLimits& limits() const { return limits_; }
    void setSpindleStoppedSensor(const SpindleStoppedSensor& sensor) { spindleSensor_ = sensor; }
    void addLink(const IoLink& link) { links_.push_back(link); }
    // Holds an input at a level for the whole run (`m350-sim --input IN11=0`), whatever drives it.
    void forceInput(int port, int level) { setInputFault(port, InputFault::stuck(level)); }
    // Puts a fault on an input (stuck, delayed, bouncing), or takes it off (nullopt).
    void setInputFault(int port, std::optional<InputFault> fault) {
        faults_[static_cast<std::size_t>(port - 1)] = fault;
    }
    // A sensor the simulated world drives (a home switch); traced as an io event on INnn.
    void setInput(int port, int level);
    // A key pressed for a while: the input reads `level` from now for `seconds`, then what drives it.
    void pulseInput(int port, int level, double seconds) {
        pulses_[static_cast<std::size_t>(port - 1)] = Pulse{level, time_, time_ + seconds};
    }
    // A sensor a device drives (the clamp cylinder's, a disc's in-position signal): from virtual time
    // `at` on, the input reads `level`. A later call for the same input cancels the changes it
    // had not reached yet, as a cylinder reversed halfway never reaches its end.
    void driveInput(int port, int level, double at);
    // The level an input reads at power-on (a released switch), before anything happens.
    void presetInput(int port, int level) { inputs_[static_cast<std::size_t>(port - 1)] = level; }
    // Feed override as a factor (the panel's 进给倍率, at most 3); `rapidToo` when param 253 lets it
    // act on G00. It applies to the moves issued from then on.
    void setFeedOverride(double factor, bool rapidToo);

    void rapid(const Axes& target) override;
    void feed(const Axes& target, double feed) override;
    void arc(const Arc& arc, double feed) override;
    ProbeResult probe(const Axes& target, double feed, int port, int level) override;
    void setToolSetter(const ToolSetter& setter) { setter_ = setter; }
    // How far the straight move from `from` to `to` drives the tool into the fixed setter, past
    // its top, beyond where the tool already stood (mm); 0 when it stays clear or leaves it.
    double setterPenetration(const Axes& from, const Axes& to) const;
    // The floating setter (浮动对刀块): a block lying on the work; its `top` trips wherever X and Y are.
    void setFloatingSetter(const ToolSetter& setter) { floatingSetter_ = setter; }
    void setHomeSwitch(int axis, const HomeSwitch& homeSwitch) { homeSwitches_[static_cast<std::size_t>(axis)] = homeSwitch; }
    const HomeSwitch& homeSwitch(int axis) const { return homeSwitches_[static_cast<std::size_t>(axis)]; }
    // The true length of the tool in the spindle (the simulated world's fact, not a parameter).
    void setToolLength(double length) { toolLength_ = length; }
    // Its true radius: a setter's stylus is touched from the side when the axes come within the
    // stylus radius plus this (0: only from above, as for a tool whose diameter nobody gave).
    void setToolRadius(double radius) { toolRadius_ = radius; }
    double toolLength() const { return toolLength_; }
    void dwell(double seconds) override;
    void blockTime(double seconds) override { time_ += seconds; }

    // Tells the observer, which plays the PMC: it may take time, switch outputs, or refuse.
    void auxiliary(int code) override;
    void spindle(SpindleState state, double rpm) override;
    void coolant(bool on) override;

    void setOutput(int port, int level) override;
    int output(int port) const override { return outputs_[static_cast<std::size_t>(port - 1)].level; }
    int input(int port) override;

    const Axes& position() const override { return position_; }
    // New coordinates for where the axes stand (homing): the home switches stay where they are.
    void setPosition(const Axes& position) override;
    double time() const override { return time_; }
    SpindleState spindleState() const override { return spindle_; }
    double spindleRpm() const override { return rpm_; }
    bool coolantOn() const override { return coolant_; }

    // Reports the changes of linked inputs due up to virtual time t (the rest come with later events).
    void reportLinkedInputs(double upTo);

    // Where the axes were at virtual time t (inside the last move, or at rest; with the history
    // kept, inside any move it holds).
    Axes positionAt(double t) const;

    // A manual move (jog, handwheel): straight to `target` at `speed` (units/s), ramping at
    // `acceleration`; traced as a feed.
    void manualMove(const Axes& target, double speed, double acceleration) {
        move(MachineEvent::Type::Feed, target, speed, acceleration, speed * 60.0);
    }
    // Brakes the last move from its speed at virtual time t at `deceleration` (a released jog key);
    // positionAt() shows the braking. Nothing changes when the move would stop sooner by itself.
    void brake(double t, double deceleration);
    // When the last move started (the clock when no move was made).
    double moveStart() const { return lastMove_ ? lastMove_->start : time_; }
    // Moves made since power-on (rapid, feed, arc, manual): the machine view tells what of a
    // preview a run has done by them.
    std::uint64_t movesMade() const { return movesMade_; }

    // The handwheel guide retraces the path: while on, every move is kept (the last kHistoryMoves)
    // so positionAt() can go back along them. Off by default: a long program keeps nothing.
    static constexpr std::size_t kHistoryMoves = 10000;
    void setKeepHistory(bool on);
    bool keepsHistory() const { return keepHistory_; }
    // The earliest virtual time positionAt() still knows.
    double historyFrom() const { return historyFrom_; }

    // What was left of an operation cut short by a hold: the rest of a move (straight or along
    // its arc), or of a dwell.
    struct Remainder {
        enum class Kind { None, Rapid, Feed, Arc, Dwell } kind = Kind::None;
        Axes target = Axes::Zero();
        double feed = 0.0;
        std::optional<Arc> arc;
        double seconds = 0.0;
    };
    // Cuts the operation running at virtual time t: a move decelerates to rest (`immediate`: stops
    // where it is, as an E-stop does), a dwell ends. The clock then reads the moment of rest. With
    // the history kept and t before the last move (a retraced guide), the machine stops where it
    // was at t and the later moves are dropped.
    Remainder interrupt(double t, bool immediate);
    // An oriented spindle (M19) stands still, held in place.
    bool spindleTurning() const {
        return (spindle_ != SpindleState::Stop && spindle_ != SpindleState::Orient) || time_ < spindleStopsAt_;
    }

    // A move of `length` along a straight line at `speed` (units/s): its duration.
    double moveDuration(double length, double speed, double acceleration) const;

private:
    struct OutputState {
        int level = 0;
        int previous = 0;
        double changedAt = -1e300;
    };
    static constexpr double kNever = std::numeric_limits<double>::infinity();
    struct LastMove {
        Axes from = Axes::Zero();
        Axes to = Axes::Zero();
        double start = 0.0;
        MotionProfile profile{0.0, 1.0, 1.0};
        std::optional<Arc> arc; // the path, when it is not a straight line
        MachineEvent::Type type = MachineEvent::Type::Feed;
        double feed = 0.0;
        double acceleration = 1.0;
        // A move cut short (hold, E-stop, released jog key): from cutAt it brakes from cutSpeed at
        // `braking` (0: stopped at once), cutDistance along its path.
        double cutAt = kNever;
        double cutSpeed = 0.0;
        double cutDistance = 0.0;
        double braking = 0.0;
    };
    static double endOf(const LastMove& m);
    static double travelledAt(const LastMove& m, double t);
    static Axes pointAlong(const LastMove& m, double distance);
    static void cut(LastMove& m, double t, double deceleration);
    void rewind(double t);
    double dwellEnd_ = -1.0;
    void move(MachineEvent::Type type, const Axes& target, double speed, double acceleration, double feed,
              const Arc* arc = nullptr);
    void reportLastMove();
    void notify(const MachineEvent& event) {
        if (observer_) {
            if (!pendingInputs_.empty()) {
                reportLinkedInputs(event.start);
            }
            observer_->onMachineEvent(event);
        }
    }

    MachineObserver* observer_;
    MotionLimits limits_;
    double feedOverride_ = 1.0;
    bool rapidOverride_ = false;
    Axes position_ = Axes::Zero();
    double time_ = 0.0;
    std::optional<LastMove> lastMove_;
    std::uint64_t movesMade_ = 0;
    bool keepHistory_ = false;
    std::deque<LastMove> history_; // oldest first; the last is a copy of lastMove_
    double historyFrom_ = 0.0;
    std::array<OutputState, kOutputCount> outputs_{};
    std::array<int, kInputCount> inputs_{};
    std::array<std::optional<InputFault>, kInputCount> faults_{};
    std::array<double, kInputCount> inputChangedAt_{};
    struct Pulse {
        int level = 0;
        double from = 0.0;
        double until = -1.0;
    };
    std::array<Pulse, kInputCount> pulses_{};
    // An input's level at virtual time t as what drives it says, with its last change.
    struct Signal {
        int level = 0;
        int previous = 0;
        double changedAt = -1e300;
    };
    Signal signalAt(int port, double t) const;
    std::vector<IoLink> links_;
    std::array<std::vector<std::pair<double, int>>, kInputCount> driven_{}; // (from, level), see driveInput
    std::optional<Signal> drivenSignal(std::size_t index, double t) const;
    void schedulePending(MachineEvent event);
    std::vector<MachineEvent> pendingInputs_; // linked input changes not yet due, in time order
    void scheduleLinkedInputs(int output);
    SpindleStoppedSensor spindleSensor_;
    ToolSetter setter_;
    ToolSetter floatingSetter_; // its radius does not matter: it lies under the tool wherever it is
    double toolLength_ = 0.0;
    double toolRadius_ = 0.0;
    bool setterPressed(const ToolSetter& setter, const Axes& at) const;
    std::optional<double> setterCrossing(const ToolSetter& setter, const Axes& target, int level) const;
    const ToolSetter* setterOn(int port) const;
    std::array<HomeSwitch, kAxisCount> homeSwitches_{};
    std::optional<int> homeSwitchAxisOn(int port) const;
    std::optional<double> homeSwitchCrossing(int axis, const Axes& target, int level) const;
    SpindleState spindle_ = SpindleState::Stop;
    double rpm_ = 0.0;
    double spindleStopsAt_ = 0.0;
    bool coolant_ = false;
};

} // namespace m350::machine
