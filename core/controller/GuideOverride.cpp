#include "core/controller/GuideOverride.h"

#include <algorithm>
#include <cmath>

namespace m350::controller {

namespace {

double toward(double value, double target, double step) {
    double next = value < target ? std::min(value + step, target) : std::max(value - step, target);
    return std::abs(next - target) < 1e-9 ? target : next; // no rounding residue short of rest
}

} // namespace

void GuideOverride::turn(int direction, double target, double seconds) {
    wheelDirection_ = direction > 0 ? 1 : -1;
    target_ = target;
    turning_ = std::max(0.0, seconds);
    still_ = 0.0;
}

int GuideOverride::direction() const {
    if (wheelDirection_ != 0 && (turning_ > 0.0 || still_ < kStepSeconds)) {
        return wheelDirection_;
    }
    return value_ > 0.0 ? 1 : value_ < 0.0 ? -1 : 0;
}

void GuideOverride::step(bool turning, const Steps& steps) {
    bool driving = turning && target_ != 0.0 && value_ * target_ >= 0.0;
    value_ = driving ? toward(value_, target_, steps.change) : toward(value_, 0.0, steps.stop);
}

double GuideOverride::advance(double seconds, const Steps& steps) {
    double progress = 0.0;
    while (seconds > 0.0) {
        if (value_ == 0.0 && turning_ <= 0.0) {
            phase_ = 0.0; // at rest until the wheel turns again
            still_ += seconds;
            break;
        }
        double slice = std::min(seconds, kStepSeconds - phase_);
        const bool turning = turning_ > 0.0; // the step at the end of the slice counts the wheel as it was during it
        progress += value_ * slice;
        still_ += turning ? 0.0 : slice;
        seconds -= slice;
        phase_ += slice;
        turning_ = turning_ - slice > 1e-12 ? turning_ - slice : 0.0;
        if (phase_ >= kStepSeconds * (1.0 - 1e-9)) {
            phase_ = 0.0;
            step(turning, steps);
        }
    }
    return progress;
}

} // namespace m350::controller
