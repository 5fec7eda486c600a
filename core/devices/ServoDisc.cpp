#include "core/devices/ServoDisc.h"

#include "core/devices/DeviceText.h"
#include "core/devices/TurnPosition.h"

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

std::optional<Message> ServoDisc::move(const Vector3d& from, const Vector3d& to, bool rapid, bool spindleTurning,
                                           double at) {
    if (turning(at) && !station_.reaches(1, from) && station_.reaches(1, to)) {
        return message("disc_down_turning", {where(to), std::to_string(atStation_)});
    }
    return station_.move(from, to, rapid, spindleTurning, at);
}

std::optional<Message> ServoDisc::drawbar(bool released, const Vector3d& nose) {
    return station_.drawbar(released, nose);
}

ServoDisc::Turn ServoDisc::turnTo(int pocket, double now, const Vector3d& nose) {
    Turn turn;
    if (pocket < 1 || pocket > pocketCount()) {
        turn.crash = message("disc_bad_pocket", {std::to_string(pocket), std::to_string(pocketCount())});
        return turn;
    }
    if (pocket == atStation_) {
        return turn;
    }
    if (station_.reaches(1, nose)) {
        const int held = station_.spindleTool();
        const int standing = station_.pocketTool(1);
        const std::string from = std::to_string(atStation_);
        const std::string to = std::to_string(pocket);
        turn.crash = held != 0       ? message("disc_turned_holding", {from, to, std::to_string(held), where(nose)})
                     : standing != 0 ? message("disc_turned_over_tool", {from, to, std::to_string(standing), where(nose)})
                                     : message("disc_turned_empty", {from, to, where(nose)});
        return turn;
    }
    const int steps = std::abs(shortestTurn(atStation_, pocket, pocketCount()));
    turnedFrom_ = atStation_;
    turnSteps_ = shortestTurn(atStation_, pocket, pocketCount());
    turnStarted_ = now;
    pockets_[static_cast<std::size_t>(atStation_ - 1)] = station_.pocketTool(1);
    atStation_ = pocket;
    station_.setPocketTool(1, pockets_[static_cast<std::size_t>(pocket - 1)]);
    turn.seconds = steps * geometry_.secondsPerPocket + geometry_.settleSeconds;
    turningUntil_ = now + turn.seconds;
    return turn;
}

double ServoDisc::turnPosition(double now) const {
    return devices::turnPosition(turnedFrom_, turnSteps_, pocketCount(), turnStarted_, geometry_.secondsPerPocket, now);
}

} // namespace m350::devices
