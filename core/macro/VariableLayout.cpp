#include "core/macro/VariableLayout.h"

#include <algorithm>

namespace m350::macro {

namespace {

// Where a FANUC control has no system variables of its own: the common area below #1000 and,
// above the additional work systems' #14001-#19988, the option ranges such as #98000-#98499.
constexpr VariableRange kCommonAreas[] = {{100, 999}, {20000, VariableLayout::kLastVariable}};

std::string text(const VariableRange& r) {
    return "#" + std::to_string(r.first) + "-#" + std::to_string(r.last);
}

} // namespace

std::vector<VariableRange> VariableLayout::commonRanges(const gcode::Dialect& dialect) const {
    if (dialect.id != gcode::DialectId::Fanuc) {
        return {};
    }
    if (common.empty()) {
        return {{100, 199}, {500, 999}};
    }
    return common;
}

int VariableLayout::workSystems(const gcode::Dialect& dialect) const {
    if (dialect.id != gcode::DialectId::Fanuc) {
        return 0;
    }
    return additionalWorkSystems < 0 ? 48 : additionalWorkSystems;
}

std::optional<std::string> VariableLayout::refusedCommon(const std::vector<VariableRange>& ranges) {
    for (const VariableRange& r : ranges) {
        if (r.first > r.last) {
            return text(r) + " runs backwards";
        }
        bool inside = std::any_of(std::begin(kCommonAreas), std::end(kCommonAreas), [&](const VariableRange& area) {
            return r.first >= area.first && r.last <= area.last;
        });
        if (!inside) {
            return text(r) + " is not a common variable range: they lie within #100-#999 or #20000-#999999 "
                             "(the numbers between are system variables)";
        }
    }
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        for (std::size_t j = i + 1; j < ranges.size(); ++j) {
            if (ranges[i].first <= ranges[j].last && ranges[j].first <= ranges[i].last) {
                return text(ranges[i]) + " and " + text(ranges[j]) + " overlap";
            }
        }
    }
    return std::nullopt;
}

} // namespace m350::macro
