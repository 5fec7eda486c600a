// The moves of the canned drilling cycles, as FANUC 0i and LinuxCNC's rs274 make them.
#include "core/interp/DrillingCycle.h"

#include <cmath>

namespace m350::interp {

namespace {

// Levels closer than this are the same level: no zero-length move between them, no extra peck.
constexpr double kLevelTolerance = 1e-9;

CycleStep rapidTo(const machine::Axes& target) {
    return CycleStep{CycleStep::Kind::Rapid, target, 0.0, machine::SpindleState::Stop};
}

CycleStep feedTo(const machine::Axes& target) {
    return CycleStep{CycleStep::Kind::Feed, target, 0.0, machine::SpindleState::Stop};
}

CycleStep dwellFor(double seconds) {
    return CycleStep{CycleStep::Kind::Dwell, machine::Axes::Zero(), seconds, machine::SpindleState::Stop};
}

CycleStep turnSpindle(machine::SpindleState state) {
    return CycleStep{CycleStep::Kind::Spindle, machine::Axes::Zero(), 0.0, state};
}

} // namespace

void DrillingCycle::plan(const machine::Axes& from, const std::vector<machine::Axes>& holes,
                         const Emit& emit) const {
    machine::Axes at = from;
    double level = from(drillAxis);
    double top = initialLevel;
    // A cycle that began below R first rises to R where the tool stands, and R is then its initial
    // level (rs274 does so; a FANUC leaves the case undefined).
    if (top < r) {
        at(drillAxis) = r;
        emit(rapidTo(at));
        top = r;
        level = r;
    }
    const double clear = returnToR ? r : top;
    for (std::size_t i = 0; i < holes.size(); ++i) {
        // Positioning runs at the level the tool stands at: for the first hole where the block
        // found it, for the others where the previous hole left it.
        at = holes[i];
        at(drillAxis) = i == 0 ? level : clear;
        emit(rapidTo(at));
        if (std::abs(at(drillAxis) - r) > kLevelTolerance) {
            at(drillAxis) = r;
            emit(rapidTo(at));
        }
        drill(at, clear, emit);
    }
}

void DrillingCycle::drill(const machine::Axes& atR, double clear, const Emit& emit) const {
    auto level = [&](double value) {
        machine::Axes target = atR;
        target(drillAxis) = value;
        return target;
    };
    switch (code) {
    case 73:
    case 83:
        // Each peck ends at R - k*Q, as on both controls; G73 backs off by d to break the chip, G83
        // leaves the hole to R and comes back to d above the depth already drilled.
        for (int k = 1;; ++k) {
            double depth = r - k * peck;
            if (depth <= bottom + kLevelTolerance) {
                break;
            }
            emit(feedTo(level(depth)));
            if (code == 83) {
                emit(rapidTo(level(r)));
            }
            emit(rapidTo(level(depth + peckClearance)));
        }
        emit(feedTo(level(bottom)));
        emit(rapidTo(level(clear)));
        return;
    case 74:
    case 84: {
        // The tap leaves the hole at the feed with the spindle reversed, to R (FANUC); G98 then
        // rapids on to the initial level. Feed override is not suspended while tapping.
        bool rightHand = code == 84;
        emit(feedTo(level(bottom)));
        if (dwell > 0.0) {
            emit(dwellFor(dwell));
        }
        emit(turnSpindle(rightHand ? machine::SpindleState::Reverse : machine::SpindleState::Forward));
        emit(feedTo(level(r)));
        emit(turnSpindle(rightHand ? machine::SpindleState::Forward : machine::SpindleState::Reverse));
        if (std::abs(clear - r) > kLevelTolerance) {
            emit(rapidTo(level(clear)));
        }
        return;
    }
    default: // 81, and 82 with its dwell
        emit(feedTo(level(bottom)));
        if (code == 82 && dwell > 0.0) {
            emit(dwellFor(dwell));
        }
        emit(rapidTo(level(clear)));
        return;
    }
}

} // namespace m350::interp
