#pragma once

#include "core/common/Message.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace m350::devices {

// A tool the spindle let go of with no pocket or clip under it: it lies on the table, below where
// the nose stood (machine X Y Z) when the drawbar released it.
struct FallenTool {
    int tool = 0;
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
};

// A tool magazine as a device beside the machine. It knows only signals and positions: every move
// of the spindle nose (machine X Y Z, where the nose stands when a held tool sits in a pocket), the
// drawbar, whether the spindle turns, and its own actuators, which the concrete devices take. It
// keeps where every tool is (spindle, pocket, dropped) and answers each event with what real
// hardware would suffer (a message saying what happened and where), or nothing.
class Magazine {
public:
    virtual ~Magazine() = default;

    // The spindle nose moved from `from` to `to` in a straight line, starting at virtual time `at`.
    virtual std::optional<Message> move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid,
                                            bool spindleTurning, double at) = 0;
    // The drawbar was released (true) or clamped (false) with the nose at `at`.
    virtual std::optional<Message> drawbar(bool released, const Eigen::Vector3d& at) = 0;
    // The last move stopped at `at`, short of its end (a hold, RESET, E-stop, the time limit): what
    // the device took from where that move was going (the nose in a fork, over a tool) it takes
    // from where the nose really stands.
    virtual void stoppedAt(const Eigen::Vector3d& at) { (void)at; }
    // The spindle started, stopped or oriented (M19); only a device the spindle's keys meet cares.
    virtual void spindle(bool turning, bool oriented) {
        (void)turning;
        (void)oriented;
    }

    virtual int spindleTool() const = 0;
    virtual int pocketCount() const = 0;
    virtual int pocketTool(int pocket) const = 0; // 0: empty
    virtual const std::vector<FallenTool>& droppedTools() const = 0;
};

} // namespace m350::devices
