#pragma once

#include "core/controller/GuideOverride.h"
#include "core/controller/ManualModes.h"

namespace m350::controller {

// ManualControl's settings and what is under way, kept apart from the run's state.
struct ManualMotionState {
    JogMode mode = JogMode::Continuous;
    double step = 0.1;          // mm (deg) per STEP press
    bool highSpeed = false;     // 高速: params 40-44, else 低速 45-49
    double jogOverride = 100.0; // 手动倍率 SJR, %
    double spindleOverride = 100.0; // 主轴倍率 SRO, %
    int heldAxis = -1;          // the axis whose CONT key is down
    double movingUntil = 0.0;   // virtual time the last manual move ends
    bool guide = false;         // 试切
    GuideReverse reverse = GuideReverse::Retrace;
    GuideOverride override;
};

} // namespace m350::controller
