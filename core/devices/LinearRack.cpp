#include "core/devices/LinearRack.h"

#include "core/devices/DeviceText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace m350::devices {

using Eigen::Vector3d;

namespace {

constexpr double kZoneMargin = 10.0; // the magazine zone reaches this far around a pocket

std::string at(const Vector3d& p) {
    return text::position(p);
}

using text::millimetres;
using text::number;

} // namespace

namespace {

// Over a tool standing in its pocket: where an empty nose reaches down onto its pull stud, and
// where anything moving sideways hits it.
LinearRack::Box column(const Vector3d& p, double tolerance, double height) {
    return {p - Vector3d::Constant(tolerance), p + Vector3d(tolerance, tolerance, height)};
}

} // namespace

LinearRack::LinearRack(Geometry geometry, std::vector<int> pocketTools, int spindleTool)
    : geometry_(std::move(geometry)), pockets_(std::move(pocketTools)), spindle_(spindleTool) {
    pockets_.resize(geometry_.pockets.size(), 0);
    for (int k = 1; k <= pocketCount(); ++k) {
        const Vector3d& p = geometry_.pockets[static_cast<std::size_t>(k - 1)];
        boxes_.push_back({region(k), column(p, geometry_.tolerance, geometry_.forkDepth), zone(k)});
        const Box& z = boxes_.back().zone;
        envelope_ = envelope_ ? Box{envelope_->low.cwiseMin(z.low), envelope_->high.cwiseMax(z.high)} : z;
    }
}

LinearRack::Box LinearRack::region(int k) const {
    const Vector3d& p = geometry_.pockets[static_cast<std::size_t>(k - 1)];
    const double t = geometry_.tolerance;
    Box b{p - Vector3d::Constant(t), p + Vector3d::Constant(t)};
    if (geometry_.loading == Loading::Top) {
        b.high.z() = p.z() + geometry_.forkDepth;
    } else if (geometry_.openingY > 0) {
        b.high.y() = p.y() + geometry_.forkDepth;
    } else {
        b.low.y() = p.y() - geometry_.forkDepth;
    }
    return b;
}

// The magazine zone of a pocket: its fork, the tool standing in it and the room around and above.
LinearRack::Box LinearRack::zone(int k) const {
    const Vector3d& p = geometry_.pockets[static_cast<std::size_t>(k - 1)];
    Box z = region(k);
    Box over = column(p, geometry_.tolerance, geometry_.forkDepth);
    z.low = z.low.cwiseMin(over.low) - Vector3d(kZoneMargin, kZoneMargin, kZoneMargin);
    z.high = z.high.cwiseMax(over.high) + Vector3d(kZoneMargin, kZoneMargin, 0.0);
    z.high.z() = std::max(z.high.z(), p.z() + geometry_.zoneAbove);
    return z;
}

bool LinearRack::reaches(int k, const Vector3d& nose) const {
    const Vector3d& p = geometry_.pockets[static_cast<std::size_t>(k - 1)];
    const double around = geometry_.tolerance + kZoneMargin;
    return std::abs(nose.x() - p.x()) <= around && std::abs(nose.y() - p.y()) <= around &&
           nose.z() < p.z() + geometry_.forkDepth - kStill;
}

bool LinearRack::inside(const Box& box, const Vector3d& p) {
    return (p.array() >= box.low.array() - kStill).all() && (p.array() <= box.high.array() + kStill).all();
}

// Whether the straight move passes through the box (slab test).
bool LinearRack::crosses(const Box& box, const Vector3d& from, const Vector3d& to) {
    if (apart(box, from, to)) {
        return false;
    }
    double enter = 0.0;
    double leave = 1.0;
    for (int i = 0; i < 3; ++i) {
        double d = to(i) - from(i);
        if (std::abs(d) < kStill) {
            if (from(i) < box.low(i) - kStill || from(i) > box.high(i) + kStill) {
                return false;
            }
            continue;
        }
        double t1 = (box.low(i) - from(i)) / d;
        double t2 = (box.high(i) - from(i)) / d;
        enter = std::max(enter, std::min(t1, t2));
        leave = std::min(leave, std::max(t1, t2));
    }
    return enter <= leave;
}

bool LinearRack::alongEntry(const Vector3d& from, const Vector3d& to) const {
    Vector3d d = (to - from).cwiseAbs();
    return geometry_.loading == Loading::Top ? d.x() < kStill && d.y() < kStill : d.x() < kStill && d.z() < kStill;
}

int LinearRack::pocketAt(const Vector3d& p) const {
    for (int k = 1; k <= pocketCount(); ++k) {
        if (inside(regionOf(k), p)) {
            return k;
        }
    }
    return 0;
}

std::optional<Message> LinearRack::move(const Vector3d& from, const Vector3d& to, bool rapid,
                                            bool spindleTurning, double /*at: a fixed rack does not change*/) {
    if ((to - from).squaredNorm() < kStill * kStill) {
        return std::nullopt;
    }
    if (engaged_ == 0 && (!envelope_ || !crosses(*envelope_, from, to))) {
        // Far from the rack: nothing to hit, nothing to engage, and no part of the move that
        // stoppedAt would have to take again.
        lastMove_.reset();
        return std::nullopt;
    }
    lastMove_ = MoveUnderWay{from, rapid, spindleTurning, engaged_};
    for (int k = 1; rapid && k <= pocketCount(); ++k) {
        if (crosses(zoneOf(k), from, to)) {
            return message("rack_rapid_zone", {number(k), at(from), at(to)});
        }
    }
    return spindle_.tool() != 0 ? moveHolding(from, to) : moveEmpty(from, to, spindleTurning);
}

std::optional<Message> LinearRack::moveHolding(const Vector3d& from, const Vector3d& to) {
    const int held = spindle_.tool();
    if (engaged_ != 0) {
        const int k = engaged_;
        if (!alongEntry(from, to)) {
            const char* axis = std::abs(to.x() - from.x()) >= kStill ? "X" : std::abs(to.y() - from.y()) >= kStill ? "Y" : "Z";
            return message("rack_moved_in_fork", {axis, number(held), number(k), at(from)});
        }
        if (!inside(regionOf(k), to)) {
            engaged_ = 0; // slid out of its fork with the tool
        }
        return std::nullopt;
    }
    for (int k = 1; k <= pocketCount(); ++k) {
        const int standing = pockets_[static_cast<std::size_t>(k - 1)];
        if (standing != 0 && (crosses(regionOf(k), from, to) || crosses(columnOf(k), from, to))) {
            return message("rack_tool_hit_tool", {number(held), number(standing), number(k), at(from), at(to)});
        }
        if (standing == 0 && crosses(regionOf(k), from, to)) {
            if (!alongEntry(from, to)) {
                return message("rack_tool_hit_fork", {number(held), number(k), geometry_.loading == Loading::Top ? "Z" : "Y",
                                                      at(from), at(to)});
            }
            if (inside(regionOf(k), to)) {
                engaged_ = k;
            }
        }
    }
    return std::nullopt;
}

std::optional<Message> LinearRack::moveEmpty(const Vector3d& from, const Vector3d& to, bool spindleTurning) {
    const bool vertical = std::abs(to.x() - from.x()) < kStill && std::abs(to.y() - from.y()) < kStill;
    if (engaged_ != 0 && vertical) {
        // the released nose rises off the tool it stood over (or goes back down onto it)
        if (!inside(columnOf(engaged_), to)) {
            engaged_ = 0;
        }
        return std::nullopt;
    }
    engaged_ = 0;
    for (int k = 1; k <= pocketCount(); ++k) {
        const int standing = pockets_[static_cast<std::size_t>(k - 1)];
        const Vector3d& p = geometry_.pockets[static_cast<std::size_t>(k - 1)];
        if (standing != 0 && vertical && to.z() < from.z() && !crosses(columnOf(k), from, to)) {
            const double off = std::hypot(to.x() - p.x(), to.y() - p.y());
            const double holderTop = p.z() + geometry_.forkDepth;
            if (off <= geometry_.holderRadius && from.z() > holderTop - kStill && to.z() < holderTop - kStill) {
                return message("rack_nose_off_centre", {number(standing), number(k), at(to), millimetres(off),
                                                        millimetres(geometry_.tolerance)});
            }
        }
        if (standing == 0 || !crosses(columnOf(k), from, to)) {
            continue;
        }
        if (!vertical) {
            return message("rack_nose_hit_tool", {number(standing), number(k), at(from), at(to)});
        }
        if (to.z() > from.z()) {
            continue; // rising from beside its pull stud (an E-stop stopped it there): nothing comes down
        }
        if (spindleTurning) {
            return message("rack_down_turning", {number(standing), number(k)});
        }
        if (!spindle_.released()) {
            return message("rack_down_clamped", {number(standing), number(k)});
        }
        if (to.z() <= p.z() + geometry_.tolerance) {
            engaged_ = k; // seated over the pull stud
        }
    }
    return std::nullopt;
}

void LinearRack::stoppedAt(const Vector3d& nose) {
    if (const std::optional<MoveUnderWay> cut = std::exchange(lastMove_, std::nullopt)) {
        engaged_ = cut->engagedBefore;
        (void)move(cut->from, nose, cut->rapid, cut->spindleTurning, 0.0); // what it hit, it hit on the way
        lastMove_.reset();
    }
}

std::optional<Message> LinearRack::drawbar(bool released, const Vector3d& nose) {
    lastMove_.reset(); // the nose stands still now
    int* pocket = engaged_ != 0 ? &pockets_[static_cast<std::size_t>(engaged_ - 1)] : nullptr;
    if (const int dropped = spindle_.change(released, pocket, nose)) {
        return message("rack_dropped", {number(dropped), at(nose)});
    }
    return std::nullopt;
}

} // namespace m350::devices
