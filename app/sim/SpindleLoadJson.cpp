#include "app/sim/SpindleLoadJson.h"

#include <cmath>

namespace m350::sim {

nlohmann::json spindleLoadJson(const controller::SpindleLoadWatch& watch, bool fanuc) {
    const tools::SpindleLoadMonitor& monitor = watch.monitor();
    nlohmann::json j;
    j["lambda"] = watch.model()->lambda;
    j["register_variable"] = fanuc ? 1032 : 2990;
    j["register"] = watch.reg();
    j["sample_ms"] = std::round(monitor.settings().sampleSeconds * 1000.0);
    j["samples_to_alarm"] = monitor.settings().samples;
    nlohmann::json limits = nlohmann::json::object();
    for (const auto& [tool, l] : monitor.settings().tools) {
        limits[std::to_string(tool)] = {{"lower", l.lower}, {"upper", l.upper}};
    }
    j["limits"] = limits;
    j["taken"] = monitor.taken();
    nlohmann::json samples = nlohmann::json::array();
    for (const tools::LoadSample& s : monitor.history()) {
        samples.push_back({std::round(s.time * 1000.0) / 1000.0, s.tool, s.percent});
    }
    j["samples"] = samples;
    return j;
}

} // namespace m350::sim
