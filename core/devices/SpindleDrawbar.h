#pragma once

#include "core/devices/Magazine.h"

#include <vector>

namespace m350::devices {

// The spindle's drawbar as a magazine sees it: the tool it holds, whether it is released, and the
// tools it let fall. Released over a pocket, its tool goes into the pocket; released over nothing,
// the tool drops; clamped over a tool standing in a pocket, the spindle takes it.
class SpindleDrawbar {
public:
    explicit SpindleDrawbar(int tool) : tool_(tool) {}

    // The drawbar switched with the nose at `nose`; `pocket` is the tool slot of the pocket the nose
    // stands in (nullptr: none). Returns the tool that dropped, 0 when none did.
    int change(bool released, int* pocket, const Eigen::Vector3d& nose) {
        if (released == released_) {
            return 0;
        }
        released_ = released;
        if (released) {
            const int held = tool_;
            tool_ = 0;
            if (held == 0 || pocket) {
                if (held != 0) {
                    *pocket = held;
                }
                return 0;
            }
            dropped_.push_back({held, nose});
            return held;
        }
        if (tool_ == 0 && pocket && *pocket != 0) {
            tool_ = *pocket;
            *pocket = 0; // still in the pocket until the spindle leaves it, but the spindle's now
        }
        return 0;
    }

    int tool() const { return tool_; }
    bool released() const { return released_; }
    const std::vector<FallenTool>& dropped() const { return dropped_; }

private:
    int tool_ = 0;
    bool released_ = false;
    std::vector<FallenTool> dropped_;
};

} // namespace m350::devices
