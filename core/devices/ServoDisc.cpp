#include "core/devices/ServoDisc.h"

#include "core/devices/DeviceText.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace m350::devices {

using Eigen::Vector3d;

namespace {

LinearRack::Geometry stationGeometry(const ServoDisc::Geometry& g) {
    LinearRack::Geometry station;
    station.pockets = {g.station};
    station.loading = LinearRack::Loading::Top;
    station.forkDepth = g.forkDepth;
    station.tolerance = g.tolerance;
    return station;
}

std::string where(const Vector3d& p) {
    return text::position(p);
}

} // namespace

ServoDisc::ServoDisc(const Geometry& geometry, std::vector<int> pocketTools, int spindleTool, int atStation)
    : geometry_(geometry), pockets_(std::move(pocketTools)),
      station_(stationGeometry(geometry), {0}, spindleTool), atStation_(atStation) {
    pockets_.resize(static_cast<std::size_t>(std::max(1, geometry_.pockets)), 0);
    if (atStation_ < 1 || atStation_ > pocketCount()) {
        atStation_ = 1;
    }
    station_.setPocketTool(1, pockets_[static_cast<std::size_t>(atStation_ - 1)]);
}

int ServoDisc::pocketTool(int pocket) const {
    return pocket == atStation_ ? station_.pocketTool(1) : pockets_[static_cast<std::size_t>(pocket - 1)];
}

std::optional<std::string> ServoDisc::move(const Vector3d& from, const Vector3d& to, bool rapid, bool spindleTurning,
                                           double at) {
    if (turning(at) && !station_.reaches(1, from) && station_.reaches(1, to)) {
        return "came down into the disc at " + where(to) + " while it was still turning to pocket " +
               std::to_string(atStation_) + ": wait for its in-position signal first";
    }
    return station_.move(from, to, rapid, spindleTurning, at);
}

std::optional<std::string> ServoDisc::drawbar(bool released, const Vector3d& nose) {
    return station_.drawbar(released, nose);
}

ServoDisc::Turn ServoDisc::turnTo(int pocket, double now, const Vector3d& nose) {
    Turn turn;
    if (pocket < 1 || pocket > pocketCount()) {
        turn.crash = "the disc was told to turn to pocket " + std::to_string(pocket) + ", but it has pockets 1-" +
                     std::to_string(pocketCount()) + ": its drive stops with a position fault";
        return turn;
    }
    if (pocket == atStation_) {
        return turn;
    }
    if (station_.reaches(1, nose)) {
        const int held = station_.spindleTool();
        const int standing = station_.pocketTool(1);
        std::string what = held != 0       ? "T" + std::to_string(held) + " in the spindle"
                           : standing != 0 ? "the spindle nose over T" + std::to_string(standing)
                                           : "the spindle nose";
        turn.crash = "the disc turned from pocket " + std::to_string(atStation_) + " to pocket " +
                     std::to_string(pocket) + " while " + what + " was inside it at " + where(nose) +
                     ": raise Z to the change height (param 806) before turning the disc";
        return turn;
    }
    const int n = pocketCount();
    const int forward = ((pocket - atStation_) % n + n) % n;
    const int steps = std::min(forward, n - forward);
    pockets_[static_cast<std::size_t>(atStation_ - 1)] = station_.pocketTool(1);
    atStation_ = pocket;
    station_.setPocketTool(1, pockets_[static_cast<std::size_t>(pocket - 1)]);
    turn.seconds = steps * geometry_.secondsPerPocket + geometry_.settleSeconds;
    turningUntil_ = now + turn.seconds;
    return turn;
}

} // namespace m350::devices
