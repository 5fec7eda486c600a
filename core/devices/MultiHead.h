#pragma once

#include "core/devices/Magazine.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::devices {

// A multi-process machine (多工序, M350 magazine type 1): up to four heads on one carriage, each
// lowered into work by its own cylinder (the IO page's outputs of params 777, 780, 783, 786:
// M168/M169 ... M174/M175). "Tool k" is head k: in use while its cylinder holds it down, parked
// while up. Nothing is handed over, so nothing drops; what goes wrong is a head coming down with
// Z low (into the work), and two heads down at once when the carriage moves.
class MultiHead : public Magazine {
public:
    // `safeZ`: the lowest nose Z at which a head may come down (param 806, the change height).
    MultiHead(int heads, double safeZ, double tolerance, int headDown);

    std::optional<Message> move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid,
                                    bool spindleTurning, double at) override;
    std::optional<Message> drawbar(bool, const Eigen::Vector3d&) override { return std::nullopt; }

    int spindleTool() const override; // the head down, 0 when none (or when several are)
    int pocketCount() const override { return static_cast<int>(down_.size()); }
    // Head k is in its own place on the carriage, or in use: two down together are neither in use.
    int pocketTool(int pocket) const override { return pocket == spindleTool() ? 0 : pocket; }
    const std::vector<FallenTool>& droppedTools() const override { return none_; }

    // Whether head k's cylinder holds it down.
    bool down(int head) const { return down_[static_cast<std::size_t>(head - 1)]; }
    // Head k's cylinder moved it down (true) or up, with the nose at `nose`.
    std::optional<Message> cylinder(int head, bool down, const Eigen::Vector3d& nose);

private:
    std::vector<bool> down_;
    double safeZ_;
    double tolerance_;
    std::vector<FallenTool> none_;
};

} // namespace m350::devices
