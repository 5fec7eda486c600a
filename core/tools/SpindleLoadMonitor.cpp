#include "core/tools/SpindleLoadMonitor.h"

#include <cstdio>

namespace m350::tools {

namespace {

std::string number(double v, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

} // namespace

std::optional<std::string> SpindleLoadMonitor::add(const LoadSample& sample) {
    history_.push_back(sample);
    if (history_.size() > kHistory) {
        history_.pop_front();
    }
    ++taken_;
    const LoadLimits* limits = settings_.limitsFor(sample.tool);
    const bool over = limits && limits->upper > 0.0 && sample.percent > limits->upper;
    const bool under = limits && sample.cutting && sample.percent < limits->lower;
    if (!over && !under) {
        outOfLimits_ = 0;
        return std::nullopt;
    }
    if (outOfLimits_++ == 0) {
        outSince_ = sample.time;
    }
    if (outOfLimits_ < settings_.samples) {
        return std::nullopt;
    }
    outOfLimits_ = 0;
    return "tool " + std::to_string(sample.tool) + " spindle load out of its limits (" + number(limits->lower, 2) +
           " - " + (limits->upper > 0.0 ? number(limits->upper, 2) : std::string("none")) + " %) for " +
           std::to_string(settings_.samples) + " samples since " + number(outSince_, 2) + " s, now " +
           number(sample.percent, 2) + " % (" + (over ? "above" : "below") + "): tool broken?";
}

} // namespace m350::tools
