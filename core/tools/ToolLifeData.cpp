#include "core/tools/ToolLifeData.h"

#include "core/common/Numeric.h"
#include "core/params/FanucParameters.h"

#include <algorithm>

namespace m350::tools {

LifeCapacity lifeCapacity(int gs) {
    switch (gs) {
    case 1: return {64, 4}; // GS1
    case 2: return {32, 8}; // GS2
    case 3: return {128, 2};
    default: return {16, 16};
    }
}

void LifeData::applyFanucParameters(const std::map<int, double>& parameters) {
    const int settings = saturatingInt(params::fanucParameter(parameters, params::kToolLifeSettings));
    gs = settings & 3;
    defaultKind = (settings & 4) != 0 ? LifeKind::Minutes : LifeKind::Count;
    extendedEntry = (saturatingInt(params::fanucParameter(parameters, params::kToolLifeExtended)) & 64) != 0;
    ignoreNumber = saturatingInt(params::fanucParameter(parameters, params::kToolLifeIgnoreNumber));
    fromParameters = true;
}

LifeGroup* LifeData::group(int number) {
    auto it = std::find_if(groups.begin(), groups.end(), [number](const LifeGroup& g) { return g.number == number; });
    return it == groups.end() ? nullptr : &*it;
}

const LifeGroup* LifeData::group(int number) const {
    return const_cast<LifeData*>(this)->group(number);
}

void LifeData::putGroup(LifeGroup group) {
    auto it = std::lower_bound(groups.begin(), groups.end(), group.number,
                               [](const LifeGroup& g, int n) { return g.number < n; });
    if (it != groups.end() && it->number == group.number) {
        *it = std::move(group);
    } else {
        groups.insert(it, std::move(group));
    }
}

bool LifeData::removeGroup(int number) {
    auto it = std::find_if(groups.begin(), groups.end(), [number](const LifeGroup& g) { return g.number == number; });
    if (it == groups.end()) {
        return false;
    }
    groups.erase(it);
    return true;
}

std::optional<Message> LifeData::capacityProblem(const LifeGroup& g) const {
    LifeCapacity capacity = lifeCapacity(gs);
    const std::vector<std::string> table{std::to_string(gs & 1), std::to_string(gs >> 1), std::to_string(capacity.groups),
                                         std::to_string(capacity.toolsPerGroup)};
    if (g.number < 1 || g.number > capacity.groups) {
        std::vector<std::string> arguments{std::to_string(g.number)};
        arguments.insert(arguments.end(), table.begin(), table.end());
        return message("tool_life_capacity_groups", std::move(arguments));
    }
    if (static_cast<int>(g.tools.size()) > capacity.toolsPerGroup) {
        std::vector<std::string> arguments{std::to_string(g.number), std::to_string(g.tools.size())};
        arguments.insert(arguments.end(), table.begin(), table.end());
        return message("tool_life_capacity_tools", std::move(arguments));
    }
    return std::nullopt;
}

} // namespace m350::tools
