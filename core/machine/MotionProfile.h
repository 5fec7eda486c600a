#pragma once

#include <algorithm>
#include <cmath>

namespace m350::machine {

// A trapezoidal velocity profile along a path of `length`, starting and ending at rest (exact
// stop at each block, as the M350 does in its default mode). Computed in closed form, so a move
// of any length costs O(1) to simulate and to sample.
class MotionProfile {
public:
    // length >= 0 (mm or deg), speed > 0 (units/s), acceleration > 0 (units/s^2). Inline: every
    // move of a program makes one.
    MotionProfile(double length, double speed, double acceleration)
        : length_(std::max(length, 0.0)), acceleration_(acceleration) {
        if (length_ <= 0.0 || speed <= 0.0 || acceleration <= 0.0) {
            return;
        }
        const double rampDistance = speed * speed / acceleration; // accelerate and decelerate
        if (rampDistance >= length_) {
            peak_ = std::sqrt(length_ * acceleration); // triangle: never reaches `speed`
            accelTime_ = peak_ / acceleration;
        } else {
            peak_ = speed;
            accelTime_ = speed / acceleration;
            cruiseTime_ = (length_ - rampDistance) / speed;
        }
    }

    double duration() const { return accelTime_ * 2 + cruiseTime_; }
    double peakSpeed() const { return peak_; }
    double length() const { return length_; }

    // Distance travelled after `t` seconds (clamped to 0..duration).
    double distanceAt(double t) const;
    double speedAt(double t) const;
    // The time at which `distance` has been travelled (inverse of distanceAt).
    double timeAt(double distance) const;

private:
    double length_;
    double acceleration_;
    double peak_ = 0.0;
    double accelTime_ = 0.0;
    double cruiseTime_ = 0.0;
};

} // namespace m350::machine
