#pragma once

#include "core/common/Message.h"
#include "core/tools/SpindleLoadLimits.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

namespace m350::tools {

// One reading of the spindle load: when, which tool, the load % as the register gives it (x100
// truncated, so 3.01 for 301), and whether the tool was expected to cut.
struct LoadSample {
    double time = 0.0;
    int tool = 0;
    double percent = 0.0;
    std::uint16_t reg = 0;
    bool cutting = false;
};

// The breakage monitor: each sample is checked against its tool's limits; `samples` in a row out
// of them is an anomaly (a single spike or dip is not). The last kHistory samples are kept for a
// plot and the report.
class SpindleLoadMonitor {
public:
    static constexpr std::size_t kHistory = 600;

    void setSettings(LoadMonitorSettings settings) { settings_ = std::move(settings); }
    const LoadMonitorSettings& settings() const { return settings_; }
    bool enabled() const { return !settings_.tools.empty(); }

    // Records the sample; the alarm text when it completes a run of out-of-limit samples.
    std::optional<Message> add(const LoadSample& sample);
    // Forgets a run under way (the program stopped; the next one starts clean). The history stays.
    void restart() { outOfLimits_ = 0; }

    const std::deque<LoadSample>& history() const { return history_; }
    // How many samples were taken in all (the history holds only the last kHistory).
    std::uint64_t taken() const { return taken_; }

private:
    LoadMonitorSettings settings_;
    std::deque<LoadSample> history_;
    std::uint64_t taken_ = 0;
    int outOfLimits_ = 0;
    double outSince_ = 0.0;
};

} // namespace m350::tools
