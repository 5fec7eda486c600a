#pragma once

#include "core/devices/Magazine.h"
#include "core/devices/SpindleDrawbar.h"
#include "core/machine/MachineTypes.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace m350::devices {

// A fixed linear rack (固定直排刀库): one fork per tool at fixed machine positions. What it knows
// comes from signals and positions only: the spindle nose's moves, the drawbar's release output
// and whether the spindle turns. It tracks where every tool is (spindle, pocket, dropped) and
// answers each event with what real hardware would suffer, or nothing.
//
// A pocket's position is where the spindle nose stands when the tool it holds sits in the fork.
// Side loading: the fork opens toward +Y or -Y and a held tool enters and leaves along Y; an empty
// spindle comes down onto a tool from above. Top loading: both happen vertically.
class LinearRack : public Magazine {
public:
    enum class Loading { Side, Top };
    struct Geometry {
        std::vector<Eigen::Vector3d> pockets; // machine X Y Z of pocket 1, 2, ...
        Loading loading = Loading::Side;
        double openingY = 1.0;   // side loading: the fork opens toward +Y (1) or -Y (-1)
        double forkDepth = 30.0; // how far along its way in a held tool is engaged in a fork
        double tolerance = 1.0;  // how far off a pocket's axis still counts as in it
        double zoneAbove = 40.0; // the magazine zone reaches this far above the pockets
        // A tool holder's flange radius: an empty nose coming down within it but further off the
        // tool's axis than `tolerance` lands on the holder instead of over the pull stud (BT30's
        // flange is 46 mm across, BT40's 63 mm).
        double holderRadius = 23.0;
    };

    LinearRack(Geometry geometry, std::vector<int> pocketTools, int spindleTool);

    std::optional<Message> move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid,
                                    bool spindleTurning, double at) override;
    std::optional<Message> drawbar(bool released, const Eigen::Vector3d& at) override;
    void stoppedAt(const Eigen::Vector3d& at) override;

    int spindleTool() const override { return spindle_.tool(); }
    int pocketTool(int pocket) const override { return pockets_[static_cast<std::size_t>(pocket - 1)]; }
    int pocketCount() const override { return static_cast<int>(pockets_.size()); }
    const std::vector<FallenTool>& droppedTools() const override { return spindle_.dropped(); }
    bool released() const { return spindle_.released(); }
    const Geometry& geometry() const { return geometry_; }

    // A device that carries its pockets (a disc) puts another tool in a pocket, or takes it out.
    void setPocketTool(int pocket, int tool) { pockets_[static_cast<std::size_t>(pocket - 1)] = tool; }
    // Whether the nose stands where anything moving through the pocket hits it (or what it holds):
    // over the pocket, lower than the top of a tool standing in it.
    bool reaches(int pocket, const Eigen::Vector3d& nose) const;

    struct Box {
        Eigen::Vector3d low;
        Eigen::Vector3d high;
    };

    static constexpr double kStill = 1e-6; // an axis that moves less than this did not move

    // A move that passes wide of the rack while nothing is engaged in it: all that move() does
    // with it (forget the last move, so that stoppedAt takes none again), done inline for the
    // caller; false when move() must look at the move. Most moves of a program are far from it.
    bool passesFar(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
        if (!wideOf(from, to)) {
            return false;
        }
        lastMove_.reset();
        return true;
    }
    // Such a move with no last move to forget either: the rack need not be told of it at all.
    // (A still move far from it does nothing to the rack then either: it needs no test of its own.)
    bool ignores(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
        return !lastMove_ && engaged_ == 0 && envelope_ && apartFromEnvelope(from, to);
    }

private:
    Box region(int pocket) const;  // where the nose stands with a held tool engaged in the fork
    Box zone(int pocket) const;    // the magazine zone around one pocket
    const Box& regionOf(int pocket) const { return boxes_[static_cast<std::size_t>(pocket - 1)].region; }
    const Box& columnOf(int pocket) const { return boxes_[static_cast<std::size_t>(pocket - 1)].column; }
    const Box& zoneOf(int pocket) const { return boxes_[static_cast<std::size_t>(pocket - 1)].zone; }
    static bool inside(const Box& box, const Eigen::Vector3d& p);
    static bool crosses(const Box& box, const Eigen::Vector3d& from, const Eigen::Vector3d& to);
    // Whether the move passes wide of the box on some axis: it does not cross it, without the
    // divisions of the slab test. The margin grows with the move so that the slab test's rounding
    // cannot bring an end it puts past the box back to its edge (NaN compares false: not apart).
    static bool apartOn(const Box& box, const Eigen::Vector3d& from, const Eigen::Vector3d& to, int i) {
        const double margin = kStill + 1e-9 * std::abs(to(i) - from(i));
        const double below = box.low(i) - margin;
        const double above = box.high(i) + margin;
        return (from(i) < below && to(i) < below) || (from(i) > above && to(i) > above);
    }
    static bool apart(const Box& box, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
        return apartOn(box, from, to, 0) || apartOn(box, from, to, 1) || apartOn(box, from, to, 2);
    }
    // apart() from the envelope, trying first the axis that told the last move apart: a program's
    // moves mostly keep to one side of the rack. The answer is the same in any order.
    bool apartFromEnvelope(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
        if (apartOn(*envelope_, from, to, apartAxis_)) {
            return true;
        }
        for (int i = 0; i < 3; ++i) {
            if (i != apartAxis_ && apartOn(*envelope_, from, to, i)) {
                apartAxis_ = i;
                return true;
            }
        }
        return false;
    }
    // Nothing engaged and the move apart from every zone (the box test first: it decides nearly
    // every move); a still move goes to move() as well.
    bool wideOf(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
        return engaged_ == 0 && envelope_ && apartFromEnvelope(from, to) && (to - from).squaredNorm() >= kStill * kStill;
    }
    bool alongEntry(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;
    int pocketAt(const Eigen::Vector3d& p) const; // 0 when none
    std::optional<Message> moveHolding(const Eigen::Vector3d& from, const Eigen::Vector3d& to);
    std::optional<Message> moveEmpty(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool spindleTurning);

    Geometry geometry_;
    // Each pocket's boxes, made once (the rack does not move), and the box around every zone: a
    // move that stays out of it touches nothing of the rack, which is decided at O(1) cost.
    struct PocketBoxes {
        Box region;
        Box column; // over a tool standing in the pocket (see column() in LinearRack.cpp)
        Box zone;
    };
    std::vector<PocketBoxes> boxes_;
    std::optional<Box> envelope_;
    mutable int apartAxis_ = 0; // the axis apartFromEnvelope tries first
    std::vector<int> pockets_; // tool in each pocket, 0 empty
    SpindleDrawbar spindle_;
    int engaged_ = 0;          // the pocket whose fork holds the spindle's tool (or whose tool the
                               // released nose stands over), 0 when none
    struct MoveUnderWay {
        Eigen::Vector3d from;
        bool rapid = false;
        bool spindleTurning = false;
        int engagedBefore = 0;
    };
    std::optional<MoveUnderWay> lastMove_; // taken again to where it stopped (stoppedAt)
};

} // namespace m350::devices
