#include "core/machine/ToolWorld.h"

#include <algorithm>

namespace m350::machine {

std::optional<double> ToolWorld::entry(const std::vector<double>& values, int tool) {
    if (tool < 1 || static_cast<std::size_t>(tool) > values.size()) {
        return std::nullopt;
    }
    return values[static_cast<std::size_t>(tool - 1)];
}

double ToolWorld::length(int tool, double t) const {
    double length = nominalLength(tool);
    for (const ToolBreak& b : breaks_) {
        if (b.tool == tool && b.at <= t) {
            length -= b.shortBy;
        }
    }
    return std::max(0.0, length);
}

bool ToolWorld::broken(int tool, double t) const {
    std::optional<double> at = breakTime(tool);
    return at && *at <= t;
}

std::optional<double> ToolWorld::breakTime(int tool) const {
    std::optional<double> first;
    for (const ToolBreak& b : breaks_) {
        if (b.tool == tool && (!first || b.at < *first)) {
            first = b.at;
        }
    }
    return first;
}

} // namespace m350::machine
