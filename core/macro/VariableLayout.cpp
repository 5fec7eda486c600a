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

std::optional<Message> VariableLayout::refusedCommon(const std::vector<VariableRange>& ranges) {
    for (const VariableRange& r : ranges) {
        if (r.first > r.last) {
            return message("common_range_backwards", {text(r)});
        }
        bool inside = std::any_of(std::begin(kCommonAreas), std::end(kCommonAreas), [&](const VariableRange& area) {
            return r.first >= area.first && r.last <= area.last;
        });
        if (!inside) {
            return message("common_range_outside", {text(r)});
        }
    }
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        for (std::size_t j = i + 1; j < ranges.size(); ++j) {
            if (ranges[i].first <= ranges[j].last && ranges[j].first <= ranges[i].last) {
                return message("common_range_overlap", {text(ranges[i]), text(ranges[j])});
            }
        }
    }
    return std::nullopt;
}

} // namespace m350::macro
