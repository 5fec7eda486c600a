#include "core/devices/UmbrellaCarousel.h"

#include "core/devices/DeviceText.h"

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

using text::pocket;
using text::tool;

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

std::optional<std::string> UmbrellaCarousel::move(const Vector3d& from, const Vector3d& to, bool /*rapid*/,
                                                   bool spindleTurning, double at) {
    if (!slideIn_ || (to - from).norm() < kStill) {
        return std::nullopt;
    }
    lastMove_ = MoveUnderWay{from, spindleTurning, at, engaged_};
    if (std::abs(to.x() - from.x()) >= kStill || std::abs(to.y() - from.y()) >= kStill) {
        const char* axis = std::abs(to.x() - from.x()) >= kStill ? "X" : "Y";
        return std::string("moved ") + axis + " while the carousel stood at the spindle (from " + where(from) +
               " to " + where(to) + "): slide it back (M84) first";
    }
    if (busy(at) && to.z() < geometry_.clearZ - geometry_.tolerance) {
        return "came down into the carousel at " + where(to) + " while it was still turning or sliding";
    }
    if (spindle_.tool() != 0) {
        // only at the change height, in its clip: any Z move tears the clamped tool out of it
        return "Z moved from " + where(from) + " to " + where(to) + " while " + tool(spindle_.tool()) +
               " was clamped in the spindle and held by the clip of " + pocket(atSpindle_) +
               ": release it (M11) first, or slide the carousel back (M84)";
    }
    return moveEmpty(from, to, spindleTurning);
}

std::optional<std::string> UmbrellaCarousel::moveEmpty(const Vector3d& from, const Vector3d& to, bool spindleTurning) {
    const int standing = clip();
    const double tol = geometry_.tolerance;
    if (to.z() >= geometry_.clearZ - tol) {
        engaged_ = false; // up and clear of the tools
        return std::nullopt;
    }
    if (standing == 0) {
        if (to.z() < geometry_.gripZ - tol) {
            return "the spindle nose hit the empty clip of " + pocket(atSpindle_) + " at " + where(to) +
                   ": the change height is Z" + text::millimetres(geometry_.gripZ) + " (G30 P3)";
        }
        return std::nullopt;
    }
    if (to.z() < from.z() && !engaged_) {
        if (spindleTurning || turning_) {
            return "came down onto " + tool(standing) + " in " + pocket(atSpindle_) +
                   " with the spindle turning: stop and orient it (M19) first";
        }
        if (!spindle_.released()) {
            return "came down onto " + tool(standing) + " in " + pocket(atSpindle_) +
                   " with the drawbar clamped: release it (M11) before coming down";
        }
        if (!oriented_) {
            return "the spindle's drive keys came down onto " + tool(standing) + "'s holder in " +
                   pocket(atSpindle_) + ": orient the spindle (M19) first";
        }
    }
    if (to.z() < geometry_.gripZ - tol) {
        return "pushed " + tool(standing) + " in " + pocket(atSpindle_) + " down out of its clip: the nose went to " +
               where(to) + ", below the change height (G30 P3)";
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

std::optional<std::string> UmbrellaCarousel::drawbar(bool released, const Vector3d& nose) {
    lastMove_.reset(); // the nose stands still now
    if (const int dropped = spindle_.change(released, engaged_ ? &clip() : nullptr, nose)) {
        return tool(dropped) + " dropped: the spindle released it at " + where(nose) +
               (slideIn_ ? " out of its clip's reach (the change height is G30 P3)"
                         : " with the carousel away from the spindle (slide it in with M83 first)");
    }
    return std::nullopt;
}

std::optional<std::string> UmbrellaCarousel::slideIn(const Vector3d& nose) {
    const int standing = clip();
    const double tol = geometry_.tolerance;
    if (!atChangeXY(nose)) {
        return "the carousel slid in while the spindle stood at " + where(nose) +
               ", away from the change position X" + text::millimetres(geometry_.changeX) + " Y" +
               text::millimetres(geometry_.changeY) + ": it hit the spindle head";
    }
    if (spindle_.tool() != 0) {
        if (!near(nose.z(), geometry_.gripZ)) {
            return "the carousel hit " + tool(spindle_.tool()) + " in the spindle at " + where(nose) +
                   ": with a tool in the spindle it comes in at the change height only (G30 P3)";
        }
        if (standing != 0) {
            return tool(spindle_.tool()) + " in the spindle ran into " + tool(standing) + " in " + pocket(atSpindle_) +
                   ": the pocket at the spindle must be the empty one of the tool being returned";
        }
        if (turning_) {
            return "the clip of " + pocket(atSpindle_) + " hit " + tool(spindle_.tool()) +
                   " turning in the spindle: stop and orient it (M19) first";
        }
        if (!oriented_) {
            return "the clip of " + pocket(atSpindle_) + " hit " + tool(spindle_.tool()) +
                   "'s holder out of line with its key: orient the spindle (M19) first";
        }
        engaged_ = true;
        return std::nullopt;
    }
    if (nose.z() < geometry_.clearZ - tol && (standing != 0 || nose.z() < geometry_.gripZ - tol)) {
        return (standing != 0 ? tool(standing) + " in " + pocket(atSpindle_) : std::string("the carousel")) +
               " ran into the spindle nose at " + where(nose) +
               ": an empty spindle waits above the tools (G30 P2) for the carousel";
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
        action.crash = std::string("the carousel slid ") + (toSpindle ? "in" : "back") +
                       " while it was still turning: wait for its in-position signal";
    } else if (toSpindle) {
        action.crash = slideIn(nose);
    } else if (engaged_ && spindle_.tool() == 0 && clip() != 0) {
        action.crash = "the carousel pulled " + tool(clip()) + " sideways out of the open spindle nose at " +
                       where(nose) + ": raise Z (G30 P2) after releasing it, or clamp it (M10) first";
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
        action.crash = "the carousel was told to turn to " + pocket(target) + ", but it has pockets 1-" +
                       std::to_string(pocketCount());
        return action;
    }
    if (target == atSpindle_) {
        return action;
    }
    if (slideIn_ && (engaged_ || nose.z() < geometry_.clearZ - geometry_.tolerance)) {
        action.crash = "the carousel turned from " + pocket(atSpindle_) + " to " + pocket(target) +
                       " while the spindle was inside it at " + where(nose) +
                       ": raise Z above the tools (G30 P2) before turning it";
        return action;
    }
    const int n = pocketCount();
    const int forward = ((target - atSpindle_) % n + n) % n;
    action.seconds = std::min(forward, n - forward) * geometry_.secondsPerPocket;
    atSpindle_ = target;
    turningUntil_ = now + action.seconds; // a new target replaces the old one, as its in-position signal does
    return action;
}

} // namespace m350::devices
