#pragma once

#include "core/devices/LinearRack.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::devices {

// A servo disc magazine (圆盘刀库, M350 magazine type 4): a disc of pockets turned by a servo drive in
// position-register mode. One pocket at a time stands at the change station, a fixed place of the
// machine, and is loaded from above: a held tool comes down into its cup, an empty spindle comes
// down onto the tool standing in it. The drive takes a target pocket, starts on a strobe, turns the
// shortest way at `secondsPerPocket` a pocket and settles; its in-position signal is off meanwhile.
//
// What it suffers besides what a rack does: turning while the spindle (or the tool it holds) is
// inside the pocket at the station, and coming down into the station while the disc turns.
class ServoDisc : public Magazine {
public:
    struct Geometry {
        Eigen::Vector3d station{0.0, 0.0, 0.0}; // nose X Y Z with a held tool seated in the station's cup
        int pockets = 8;
        double forkDepth = 30.0;
        double tolerance = 1.0;
        double secondsPerPocket = 0.25;
        double settleSeconds = 0.1;
    };

    // pocketTools[k-1] is the tool in pocket k; `atStation` is the pocket standing at the station.
    ServoDisc(const Geometry& geometry, std::vector<int> pocketTools, int spindleTool, int atStation = 1);

    std::optional<Message> move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid,
                                    bool spindleTurning, double at) override;
    std::optional<Message> drawbar(bool released, const Eigen::Vector3d& at) override;
    void stoppedAt(const Eigen::Vector3d& at) override { station_.stoppedAt(at); }

    int spindleTool() const override { return station_.spindleTool(); }
    int pocketCount() const override { return static_cast<int>(pockets_.size()); }
    int pocketTool(int pocket) const override;
    const std::vector<FallenTool>& droppedTools() const override { return station_.droppedTools(); }

    // The strobe: the drive turns to `pocket` from virtual time `now`, with the nose at `nose`.
    // A crash message when the spindle is in the way; otherwise the turn's duration (0 when the
    // pocket already stands at the station), after which the drive is in position.
    struct Turn {
        std::optional<Message> crash;
        double seconds = 0.0;
    };
    Turn turnTo(int pocket, double now, const Eigen::Vector3d& nose);
    int pocketAtStation() const { return atStation_; }
    bool turning(double now) const { return now < turningUntil_; }
    const Geometry& geometry() const { return geometry_; }
    // Which pocket faces the station at virtual time `now`, counted on past the last one while the
    // disc turns (2.5: halfway from pocket 2 to 3; 10.5 on a 10-pocket disc: halfway from 10 to 1).
    // pocketAtStation() once the turn's travel is done (the drive settles still).
    double turnPosition(double now) const;

private:
    Geometry geometry_;
    std::vector<int> pockets_; // tool in each pocket; the station's own pocket is kept by station_
    LinearRack station_;       // the pocket at the station, as a one-pocket top-loading rack
    int atStation_ = 1;
    double turningUntil_ = -1.0;
    int turnedFrom_ = 1;      // the pocket at the station when the last turn began
    int turnSteps_ = 0;       // that turn's pockets, + toward higher numbers
    double turnStarted_ = -1.0;
};

} // namespace m350::devices
