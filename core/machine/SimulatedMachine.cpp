#include "core/machine/SimulatedMachine.h"

#include <algorithm>

namespace m350::machine {

void SimulatedMachine::setFeedOverride(double factor, bool rapidToo) {
    feedOverride_ = std::clamp(factor, 0.0, 3.0); // the panel's limit is param 295 (50-300 %)
    rapidOverride_ = rapidToo;
}

double SimulatedMachine::moveDuration(double length, double speed, double acceleration) const {
    return MotionProfile(length, speed, acceleration).duration();
}

void SimulatedMachine::move(MachineEvent::Type type, const Axes& target, double speed, double acceleration,
                            double feed, const Arc* arc) {
    double length = arc ? arc->length : (target - position_).norm();
    ++movesMade_;
    if (!lastMove_) {
        // not emplace(): clang decides LastMove is not default-constructible while the class is incomplete
        lastMove_ = LastMove{};
    }
    LastMove& last = *lastMove_; // assigned in place: this runs for every move of a 200,000-line program
    last.from = position_;
    last.to = target;
    last.start = time_;
    last.profile = MotionProfile(length, speed, acceleration);
    if (arc) {
        last.arc = *arc;
    } else {
        last.arc.reset();
    }
    last.type = type;
    last.feed = feed;
    last.acceleration = acceleration;
    last.cutAt = kNever;
    time_ += last.profile.duration();
    if (keepHistory_) {
        history_.push_back(last);
        if (history_.size() > kHistoryMoves) {
            history_.pop_front();
            historyFrom_ = history_.front().start;
        }
    }
    position_ = target;
    // no event for a straight move the observer ignores, unless linked inputs wait to be reported with one
    if (observer_ && (arc || !pendingInputs_.empty() || !observer_->ignoresMove(last.from, target))) {
        reportLastMove();
    }
}

void SimulatedMachine::reportLastMove() {
    const LastMove& last = *lastMove_;
    // built in one go: a default MachineEvent zeroes both positions before they are assigned
    const MachineEvent event{.type = last.type,
                             .from = last.from,
                             .to = last.to,
                             .feed = last.feed,
                             .start = last.start,
                             .end = time_,
                             .arc = last.arc ? &*last.arc : nullptr};
    notify(event);
}

void SimulatedMachine::rapid(const Axes& target) {
    double speed = std::min(limits_.rapidSpeed, limits_.maxSpeed) * (rapidOverride_ ? feedOverride_ : 1.0);
    move(MachineEvent::Type::Rapid, target, speed, limits_.rapidAcceleration, 0.0);
}

void SimulatedMachine::feed(const Axes& target, double feed) {
    double speed = std::min(feed / 60.0, limits_.maxSpeed) * feedOverride_;
    move(MachineEvent::Type::Feed, target, speed, limits_.feedAcceleration, feed);
}

void SimulatedMachine::arc(const Arc& arc, double feed) {
    double speed = std::min(feed / 60.0, limits_.maxSpeed) * feedOverride_;
    move(MachineEvent::Type::Arc, arc.end, speed, limits_.feedAcceleration, feed, &arc);
}

SimulatedMachine::Remainder SimulatedMachine::interrupt(double t, bool immediate) {
    Remainder rest;
    if (t >= time_) {
        return rest; // nothing is running at t
    }
    if (dwellEnd_ > t) {
        rest.kind = Remainder::Kind::Dwell;
        rest.seconds = dwellEnd_ - t;
        time_ = t;
        dwellEnd_ = -1.0;
        return rest;
    }
    if (lastMove_ && t < lastMove_->start && !history_.empty()) {
        rewind(t);
        return rest;
    }
    if (!lastMove_ || t < lastMove_->start) {
        time_ = t;
        return rest;
    }
    LastMove& m = *lastMove_;
    double elapsed = t - m.start;
    double travelled = travelledAt(m, t);
    double speed = t < m.cutAt ? m.profile.speedAt(elapsed) : 0.0;
    double stopping = immediate ? 0.0 : speed * speed / (2.0 * m.acceleration);
    double stopAt = std::min(m.profile.length(), travelled + stopping);
    position_ = pointAlong(m, stopAt);
    time_ = t + (immediate ? 0.0 : speed / m.acceleration);
    if (keepHistory_ && !history_.empty() && t < m.cutAt) {
        cut(history_.back(), t, immediate ? 0.0 : m.acceleration); // a retrace passes the stop as it was
    }
    if (stopAt < m.profile.length() - 1e-9) {
        rest.kind = m.type == MachineEvent::Type::Rapid ? Remainder::Kind::Rapid
                    : m.arc                             ? Remainder::Kind::Arc
                                                        : Remainder::Kind::Feed;
        rest.target = m.to;
        rest.feed = m.feed;
        rest.arc = m.arc;
    }
    lastMove_.reset();
    return rest;
}

double SimulatedMachine::endOf(const LastMove& m) {
    if (m.cutAt == kNever) {
        return m.start + m.profile.duration();
    }
    return m.cutAt + (m.braking > 0.0 ? m.cutSpeed / m.braking : 0.0);
}

double SimulatedMachine::travelledAt(const LastMove& m, double t) {
    if (t <= m.start) {
        return 0.0;
    }
    if (t < m.cutAt) {
        return m.profile.distanceAt(t - m.start);
    }
    double braking = std::min(t - m.cutAt, m.braking > 0.0 ? m.cutSpeed / m.braking : 0.0);
    return m.cutDistance + m.cutSpeed * braking - 0.5 * m.braking * braking * braking;
}

Axes SimulatedMachine::pointAlong(const LastMove& m, double distance) {
    if (m.arc) {
        return m.arc->pointAt(distance);
    }
    double length = m.profile.length();
    return length > 0.0 ? Axes(m.from + (m.to - m.from) * (distance / length)) : m.from;
}

void SimulatedMachine::cut(LastMove& m, double t, double deceleration) {
    m.cutDistance = travelledAt(m, t);
    m.cutSpeed = deceleration > 0.0 ? m.profile.speedAt(t - m.start) : 0.0;
    m.braking = deceleration;
    m.cutAt = t;
}

void SimulatedMachine::brake(double t, double deceleration) {
    if (!lastMove_ || lastMove_->cutAt != kNever || t >= endOf(*lastMove_) || deceleration <= 0.0) {
        return;
    }
    LastMove& m = *lastMove_;
    t = std::max(t, m.start);
    double speed = m.profile.speedAt(t - m.start);
    double stopAt = travelledAt(m, t) + speed * speed / (2.0 * deceleration);
    if (stopAt >= m.profile.length()) {
        return; // its own ramp down ends it sooner (the soft limit, the step's end)
    }
    cut(m, t, deceleration);
    position_ = pointAlong(m, stopAt);
    time_ = endOf(m);
    if (keepHistory_ && !history_.empty()) {
        history_.back() = m;
    }
}

// The machine goes back to where it was at t (before the last move): the moves after t are
// dropped, the one under way at t stops there.
void SimulatedMachine::rewind(double t) {
    position_ = positionAt(t);
    time_ = t;
    dwellEnd_ = -1.0;
    while (!history_.empty() && history_.back().start > t) {
        history_.pop_back();
    }
    if (!history_.empty() && t < endOf(history_.back())) {
        cut(history_.back(), t, 0.0);
    }
    lastMove_.reset();
}

void SimulatedMachine::setKeepHistory(bool on) {
    if (on == keepHistory_) {
        return;
    }
    keepHistory_ = on;
    history_.clear();
    historyFrom_ = time_;
    if (on && lastMove_) {
        history_.push_back(*lastMove_);
        historyFrom_ = lastMove_->start;
    }
}

Axes SimulatedMachine::positionAt(double t) const {
    bool past = !history_.empty() && (lastMove_ ? t < lastMove_->start : t < endOf(history_.back()));
    if (past) {
        // the newest move that started by t
        auto after = std::upper_bound(history_.begin(), history_.end(), t,
                                      [](double at, const LastMove& m) { return at < m.start; });
        if (after == history_.begin()) {
            return history_.front().from;
        }
        const LastMove& m = *(after - 1);
        return pointAlong(m, travelledAt(m, t));
    }
    if (!lastMove_ || t >= endOf(*lastMove_)) {
        return position_;
    }
    return pointAlong(*lastMove_, travelledAt(*lastMove_, t));
}

void SimulatedMachine::dwell(double seconds) {
    dwellEnd_ = time_ + seconds;
    MachineEvent event;
    event.type = MachineEvent::Type::Dwell;
    event.from = event.to = position_;
    event.start = time_;
    time_ += seconds;
    event.end = time_;
    notify(event);
}

void SimulatedMachine::auxiliary(int code) {
    MachineEvent event;
    event.type = MachineEvent::Type::Auxiliary;
    event.start = event.end = time_;
    event.port = code;
    notify(event);
}

void SimulatedMachine::spindle(SpindleState state, double rpm) {
    double effective = state == SpindleState::Stop ? 0.0 : std::min(rpm, limits_.maxSpindleRpm);
    if (state == spindle_ && effective == rpm_) {
        return;
    }
    bool starting = spindle_ == SpindleState::Stop && (state == SpindleState::Forward || state == SpindleState::Reverse);
    if (state == SpindleState::Stop && spindle_ != SpindleState::Stop) {
        spindleStopsAt_ = time_ + limits_.spindleStopDelay; // it coasts; the program goes on
    }
    spindle_ = state;
    rpm_ = effective;
    MachineEvent event;
    event.type = MachineEvent::Type::Spindle;
    event.start = time_;
    event.spindle = state;
    event.rpm = rpm_;
    if (starting) {
        time_ += limits_.spindleStartDelay; // the program waits for the spindle to reach speed
    }
    event.end = time_;
    notify(event);
}

void SimulatedMachine::coolant(bool on) {
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

} // namespace m350::machine
