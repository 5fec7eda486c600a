#include "core/machine/MotionProfile.h"

#include <cmath>

namespace m350::machine {

double MotionProfile::distanceAt(double t) const {
    if (t <= 0.0 || peak_ == 0.0) {
        return 0.0;
    }
    if (t >= duration()) {
        return length_;
    }
    double ramp = 0.5 * acceleration_ * accelTime_ * accelTime_;
    if (t < accelTime_) {
        return 0.5 * acceleration_ * t * t;
    }
    if (t < accelTime_ + cruiseTime_) {
        return ramp + peak_ * (t - accelTime_);
    }
    double left = duration() - t;
    return length_ - 0.5 * acceleration_ * left * left;
}

double MotionProfile::speedAt(double t) const {
    if (t <= 0.0 || t >= duration()) {
        return 0.0;
    }
    if (t < accelTime_) {
        return acceleration_ * t;
    }
    if (t < accelTime_ + cruiseTime_) {
        return peak_;
    }
    return acceleration_ * (duration() - t);
}

double MotionProfile::timeAt(double distance) const {
    if (distance <= 0.0 || peak_ == 0.0) {
        return 0.0;
    }
    if (distance >= length_) {
        return duration();
    }
    double ramp = 0.5 * acceleration_ * accelTime_ * accelTime_;
    if (distance < ramp) {
        return std::sqrt(2.0 * distance / acceleration_);
    }
    if (distance <= length_ - ramp) {
        return accelTime_ + (distance - ramp) / peak_;
    }
    return duration() - std::sqrt(2.0 * (length_ - distance) / acceleration_);
}

} // namespace m350::machine
