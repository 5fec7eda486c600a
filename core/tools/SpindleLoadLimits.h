#pragma once

#include "core/common/Message.h"

#include <map>
#include <optional>
#include <string>

namespace m350::tools {

// A tool's band of normal spindle load, % of rated output. `lower` is checked only while the tool
// is expected to cut (a broken tool stops cutting); `upper` whenever the spindle turns.
struct LoadLimits {
    double lower = 0.0;
    double upper = 0.0; // 0: no upper limit
};

// The breakage monitor's settings (spindle-load.toml in the machine folder):
//   [monitor]
//   sample_ms = 100    how often the load is sampled
//   samples = 5        how many samples in a row out of limits raise the alarm
//   [tool.1]
//   lower = 8.0
//   upper = 60.0
struct LoadMonitorSettings {
    double sampleSeconds = 0.1;
    int samples = 5;
    std::map<int, LoadLimits> tools;
    const LoadLimits* limitsFor(int tool) const {
        auto it = tools.find(tool);
        return it == tools.end() ? nullptr : &it->second;
    }
};

inline constexpr const char* kSpindleLoadFileName = "spindle-load.toml";

// Reads spindle-load.toml; the error says where (line, column; 0 for the whole file) and what is
// wrong. A missing file is no error.
struct LoadSettingsError {
    int line = 0;
    int column = 0;
    Message message;
};
std::optional<LoadSettingsError> readLoadMonitorSettings(const std::string& path, LoadMonitorSettings& out);

} // namespace m350::tools
