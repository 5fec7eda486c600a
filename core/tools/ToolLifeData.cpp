#include "core/tools/ToolLifeData.h"

#include <algorithm>

namespace m350::tools {

LifeCapacity lifeCapacity(int gs) {
    switch (gs) {
    case 1: return {32, 8};
    case 2: return {64, 4};
    case 3: return {128, 2};
    default: return {16, 16};
    }
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

std::optional<std::string> LifeData::capacityProblem(const LifeGroup& g) const {
    LifeCapacity capacity = lifeCapacity(gs);
    std::string table = " (GS1/GS2 = " + std::to_string(gs & 1) + "/" + std::to_string(gs >> 1) + ": " +
                        std::to_string(capacity.groups) + " groups of " + std::to_string(capacity.toolsPerGroup) +
                        " tools)";
    if (g.number < 1 || g.number > capacity.groups) {
        return "group " + std::to_string(g.number) + " is beyond the groups the memory holds" + table;
    }
    if (static_cast<int>(g.tools.size()) > capacity.toolsPerGroup) {
        return "group " + std::to_string(g.number) + " has " + std::to_string(g.tools.size()) +
               " tools, more than a group holds" + table;
    }
    return std::nullopt;
}

} // namespace m350::tools
