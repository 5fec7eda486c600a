#include "core/devices/UmbrellaCarousel.h"

#include "core/devices/DeviceText.h"
#include "core/devices/TurnPosition.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace m350::devices {

using Eigen::Vector3d;

namespace {

constexpr double kStill = 1e-6;

std::string where(const Vector3d& p) {
    return text::position(p);
}

using text::number;

} // namespace

UmbrellaCarousel::UmbrellaCarousel(const Geometry& geometry, std::vector<int> pocketTools, int spindleTool,
                                   int atSpindle)
    : geometry_(geometry), pockets_(std::move(pocketTools)), spindle_(spindleTool), atSpindle_(atSpindle) {
    pockets_.resize(static_cast<std::size_t>(std::max(1, geometry_.pockets)), 0);
    if (atSpindle_ < 1 || atSpindle_ > pocketCount()) {
        atSpindle_ = 1;
    }
}

bool UmbrellaCarousel::atChangeXY(const Vector3d& nose) const {
    return std::abs(nose.x() - geometry_.changeX) <= geometry_.tolerance &&
           std::abs(nose.y() - geometry_.changeY) <= geometry_.tolerance;
}

bool UmbrellaCarousel::near(double z, double level) const {
    return std::abs(z - level) <= geometry_.tolerance;
}

std::optional<Message> UmbrellaCarousel::move(const Vector3d& from, const Vector3d& to, bool /*rapid*/,
                                                   bool spindleTurning, double at) {
    if (!slideIn_ || (to - from).norm() < kStill) {
        return std::nullopt;
    }
    lastMove_ = MoveUnderWay{from, spindleTurning, at, engaged_};
    if (std::abs(to.x() - from.x()) >= kStill || std::abs(to.y() - from.y()) >= kStill) {
        const char* axis = std::abs(to.x() - from.x()) >= kStill ? "X" : "Y";
        return message("carousel_moved_xy", {axis, where(from), where(to)});
    }
    if (busy(at) && to.z() < geometry_.clearZ - geometry_.tolerance) {
        return message("carousel_down_busy", {where(to)});
    }
    if (spindle_.tool() != 0) {
        // only at the change height, in its clip: any Z move tears the clamped tool out of it
        return message("carousel_z_clamped", {where(from), where(to), number(spindle_.tool()), number(atSpindle_)});
    }
    return moveEmpty(from, to, spindleTurning);
}

std::optional<Message> UmbrellaCarousel::moveEmpty(const Vector3d& from, const Vector3d& to, bool spindleTurning) {
    const int standing = clip();
    const double tol = geometry_.tolerance;
    if (to.z() >= geometry_.clearZ - tol) {
        engaged_ = false; // up and clear of the tools
        return std::nullopt;
    }
    if (standing == 0) {
        if (to.z() < geometry_.gripZ - tol) {
            return message("carousel_nose_hit_clip", {number(atSpindle_), where(to), text::millimetres(geometry_.gripZ)});
        }
        return std::nullopt;
    }
    if (to.z() < from.z() && !engaged_) {
        if (spindleTurning || turning_) {
            return message("carousel_down_turning", {number(standing), number(atSpindle_)});
        }
        if (!spindle_.released()) {
            return message("carousel_down_clamped", {number(standing), number(atSpindle_)});
        }
        if (!oriented_) {
            return message("carousel_keys", {number(standing), number(atSpindle_)});
        }
    }
    if (to.z() < geometry_.gripZ - tol) {
        return message("carousel_pushed_out", {number(standing), number(atSpindle_), where(to)});
    }
    engaged_ = near(to.z(), geometry_.gripZ);
    return std::nullopt;
}

void UmbrellaCarousel::stoppedAt(const Vector3d& nose) {
    if (const std::optional<MoveUnderWay> cut = std::exchange(lastMove_, std::nullopt)) {
        engaged_ = cut->engagedBefore;
        (void)move(cut->from, nose, false, cut->spindleTurning, cut->at); // what it hit, it hit on the way
        lastMove_.reset();
    }
}

std::optional<Message> UmbrellaCarousel::drawbar(bool released, const Vector3d& nose) {
    lastMove_.reset(); // the nose stands still now
    if (const int dropped = spindle_.change(released, engaged_ ? &clip() : nullptr, nose)) {
        return message(slideIn_ ? "carousel_dropped_reach" : "carousel_dropped_away", {number(dropped), where(nose)});
    }
    return std::nullopt;
}

std::optional<Message> UmbrellaCarousel::slideIn(const Vector3d& nose) {
    const int standing = clip();
    const double tol = geometry_.tolerance;
    if (!atChangeXY(nose)) {
        return message("carousel_slid_off_position", {where(nose), text::millimetres(geometry_.changeX),
                                                      text::millimetres(geometry_.changeY)});
    }
    if (spindle_.tool() != 0) {
        if (!near(nose.z(), geometry_.gripZ)) {
            return message("carousel_hit_tool_height", {number(spindle_.tool()), where(nose)});
        }
        if (standing != 0) {
            return message("carousel_pocket_full", {number(spindle_.tool()), number(standing), number(atSpindle_)});
        }
        if (turning_) {
            return message("carousel_clip_turning", {number(atSpindle_), number(spindle_.tool())});
        }
        if (!oriented_) {
            return message("carousel_clip_key", {number(atSpindle_), number(spindle_.tool())});
        }
        engaged_ = true;
        return std::nullopt;
    }
    if (nose.z() < geometry_.clearZ - tol && (standing != 0 || nose.z() < geometry_.gripZ - tol)) {
        return standing != 0 ? message("carousel_tool_hit_nose", {number(standing), number(atSpindle_), where(nose)})
                             : message("carousel_hit_nose", {where(nose)});
    }
    return std::nullopt;
}

UmbrellaCarousel::Action UmbrellaCarousel::slide(bool toSpindle, const Vector3d& nose, double now) {
    Action action;
    lastMove_.reset(); // the nose stands still now
    if (toSpindle == slideIn_) {
        return action;
    }
    if (busy(now)) {
        action.crash = message(toSpindle ? "carousel_slid_in_turning" : "carousel_slid_back_turning");
    } else if (toSpindle) {
        action.crash = slideIn(nose);
    } else if (engaged_ && spindle_.tool() == 0 && clip() != 0) {
        action.crash = message("carousel_pulled_tool", {number(clip()), where(nose)});
    }
    if (action.crash && toSpindle) {
        return action; // it stopped against what it hit, short of the spindle
    }
    // Back it goes whatever it meets (an E-stop drops its output at any moment), with what its clip holds.
    slideIn_ = toSpindle;
    engaged_ = toSpindle && engaged_;
    action.seconds = geometry_.slideSeconds;
    // a slide that reverses runs from now (an E-stop's clock may stand before the slide it stops)
    slidingUntil_ = now + action.seconds;
    return action;
}

UmbrellaCarousel::Action UmbrellaCarousel::turnTo(int target, const Vector3d& nose, double now) {
    Action action;
    if (target < 1 || target > pocketCount()) {
        action.crash = message("carousel_bad_pocket", {number(target), number(pocketCount())});
        return action;
    }
    if (target == atSpindle_) {
        return action;
    }
    if (slideIn_ && (engaged_ || nose.z() < geometry_.clearZ - geometry_.tolerance)) {
        action.crash = message("carousel_turned_inside", {number(atSpindle_), number(target), where(nose)});
        return action;
    }
    turnSteps_ = shortestTurn(atSpindle_, target, pocketCount());
    turnedFrom_ = atSpindle_;
    action.seconds = std::abs(turnSteps_) * geometry_.secondsPerPocket;
    atSpindle_ = target;
    turningUntil_ = now + action.seconds; // a new target replaces the old one, as its in-position signal does
    return action;
}

double UmbrellaCarousel::turnPosition(double now) const {
    const double started = turningUntil_ - std::abs(turnSteps_) * geometry_.secondsPerPocket;
    return devices::turnPosition(turnedFrom_, turnSteps_, pocketCount(), started, geometry_.secondsPerPocket, now);
}

double UmbrellaCarousel::slidePosition(double now) const {
    const double left = geometry_.slideSeconds > 0.0 ? std::clamp((slidingUntil_ - now) / geometry_.slideSeconds, 0.0, 1.0)
                                                     : 0.0;
    return slideIn_ ? 1.0 - left : left;
}

} // namespace m350::devices
