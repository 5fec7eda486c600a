#pragma once

#include "core/devices/Magazine.h"
#include "core/devices/SpindleDrawbar.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::devices {

// An umbrella carousel (斗笠式刀库, the FANUC paper's magazine): a disc of spring clips, one per tool
// (pocket = tool number), that slides sideways to the spindle and back and turns any pocket to the
// spindle side. No arm: the spindle itself puts a tool into a clip and takes one out.
//   - A tool in the spindle meets its clip sideways: the carousel slides in with the nose at the
//     change height (grip Z, G30 P3), the pocket at the spindle empty, the spindle stopped and
//     oriented (M19) so the drive keys meet the holder's slots.
//   - Released (M11), the tool stays in the clip and the nose rises off it to the clear height
//     (G30 P2), above the tools; the carousel may turn there.
//   - An empty nose comes down onto the tool in the clip released and oriented, clamps it (M10),
//     and the carousel slides back, letting the tool go sideways.
// Anything else is what the hardware would suffer, reported as a message.
class UmbrellaCarousel : public Magazine {
public:
    struct Geometry {
        double changeX = 0.0; // where the spindle stands when the carousel comes in (machine X Y)
        double changeY = 0.0;
        double gripZ = 0.0;   // nose Z with a tool in the spindle at its clip's height (G30 P3)
        double clearZ = 0.0;  // nose Z above the tools standing in the carousel (G30 P2)
        int pockets = 12;
        double tolerance = 1.0;
        double secondsPerPocket = 0.4;
        double slideSeconds = 1.2;
    };

    UmbrellaCarousel(const Geometry& geometry, std::vector<int> pocketTools, int spindleTool, int atSpindle);

    std::optional<Message> move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid,
                                    bool spindleTurning, double at) override;
    std::optional<Message> drawbar(bool released, const Eigen::Vector3d& at) override;
    void stoppedAt(const Eigen::Vector3d& at) override;

    int spindleTool() const override { return spindle_.tool(); }
    int pocketCount() const override { return static_cast<int>(pockets_.size()); }
    int pocketTool(int pocket) const override { return pockets_[static_cast<std::size_t>(pocket - 1)]; }
    const std::vector<FallenTool>& droppedTools() const override { return spindle_.dropped(); }

    // What an actuator command costs: the hardware's complaint, or how long the motion takes.
    struct Action {
        std::optional<Message> crash;
        double seconds = 0.0;
    };
    // M83 (toward the spindle) / M84 (back), from virtual time `now` with the nose at `nose`.
    Action slide(bool toSpindle, const Eigen::Vector3d& nose, double now);
    // M82: the pocket of the commanded tool turns to the spindle side.
    Action turnTo(int pocket, const Eigen::Vector3d& nose, double now);
    // The spindle as the carousel cares: turning, and oriented (M19).
    void spindle(bool turning, bool oriented) override {
        turning_ = turning;
        oriented_ = oriented;
    }

    bool atSpindle() const { return slideIn_; }
    int pocketAtSpindle() const { return atSpindle_; }
    const Geometry& geometry() const { return geometry_; }
    // Which pocket faces the spindle at virtual time `now`, fractional while the carousel turns
    // (as ServoDisc::turnPosition), and where the slide stands: 0 away, 1 at the spindle.
    double turnPosition(double now) const;
    double slidePosition(double now) const;

private:
    std::optional<Message> moveEmpty(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool spindleTurning);
    std::optional<Message> slideIn(const Eigen::Vector3d& nose);
    bool atChangeXY(const Eigen::Vector3d& nose) const;
    bool near(double z, double level) const;
    int& clip() { return pockets_[static_cast<std::size_t>(atSpindle_ - 1)]; }

    Geometry geometry_;
    std::vector<int> pockets_;
    SpindleDrawbar spindle_;
    int atSpindle_ = 1;      // the pocket on the spindle side
    bool slideIn_ = false;   // the carousel stands at the spindle
    bool engaged_ = false;   // the nose is in the clip at the spindle (holding its tool, or over it)
    bool turning_ = false;
    bool oriented_ = false;
    bool busy(double now) const { return now < turningUntil_ || now < slidingUntil_; }
    double turningUntil_ = -1.0;
    double slidingUntil_ = -1.0;
    int turnedFrom_ = 1;  // the pocket at the spindle when the last turn began
    int turnSteps_ = 0;   // that turn's pockets, + toward higher numbers
    struct MoveUnderWay {
        Eigen::Vector3d from;
        bool spindleTurning = false;
        double at = 0.0;
        bool engagedBefore = false;
    };
    std::optional<MoveUnderWay> lastMove_; // taken again to where it stopped (stoppedAt)
};

} // namespace m350::devices
