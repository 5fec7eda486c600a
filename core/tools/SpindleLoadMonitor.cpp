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

std::optional<Message> SpindleLoadMonitor::add(const LoadSample& sample) {
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
    const std::string tool = std::to_string(sample.tool);
    const std::string samples = std::to_string(settings_.samples);
    if (limits->upper <= 0.0) { // no upper limit: only too low a load gets here
        return message("spindle_load_below_no_upper", {tool, number(limits->lower, 2), samples, number(outSince_, 2),
                                                       number(sample.percent, 2)});
    }
    return message(over ? "spindle_load_above" : "spindle_load_below",
                   {tool, number(limits->lower, 2), number(limits->upper, 2), samples, number(outSince_, 2),
                    number(sample.percent, 2)});
}

} // namespace m350::tools
