#pragma once

#include "core/tools/SpindleLoadLimits.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace m350::controller {

// What the breakage monitor page shows, made in the core so the panel only draws it: the recent
// samples as (time s, load %), the axes' ranges, the tool's limits and the last reading.
struct SpindleLoadView {
    static constexpr double kPlotSeconds = 30.0;
    double lambda = 143.0;
    int registerVariable = 1032; // #1032 on a FANUC, #2990 on the M350
    int tool = 0;                // the tool in the spindle
    double percent = 0.0;        // the last sample (register / 100)
    int reg = 0;
    std::optional<tools::LoadLimits> limits; // the tool's, if it has any
    int samplesToAlarm = 5;
    double sampleSeconds = 0.1;
    std::vector<std::pair<double, double>> points;
    double from = 0.0, to = kPlotSeconds; // the time axis
    double top = 100.0;                   // the load axis, from 0
    std::uint64_t taken = 0;
};

} // namespace m350::controller
