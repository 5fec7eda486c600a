#include "core/tools/ToolLifeView.h"

#include <algorithm>

namespace m350::tools {

LifeView makeLifeView(const ToolLifeManager& manager) {
    const LifeData& data = manager.data();
    LifeView view;
    view.ignoreNumber = data.ignoreNumber;
    view.gs = data.gs;
    view.capacity = lifeCapacity(data.gs);
    view.inUse = manager.inUse();
    view.unreadLines = static_cast<int>(data.unreadLines.size());
    const auto selected = manager.selected();
    for (const LifeGroup& g : data.groups) {
        LifeGroupView group{g.number, g.kind, g.life, g.lifeUnits(), true, {}};
        for (const LifeTool& t : g.tools) {
            LifeToolView tool{t.tool, t.h, t.d, t.used, std::max(0, g.lifeUnits() - t.used), false, g.expired(t), false};
            tool.inUse = view.inUse && view.inUse->group == g.number && view.inUse->tool == t.tool;
            tool.selected = !tool.inUse && selected && selected->group == g.number && selected->tool == t.tool;
            group.allExpired = group.allExpired && tool.expired;
            group.tools.push_back(tool);
        }
        view.groups.push_back(std::move(group));
    }
    return view;
}

std::string lifeAmountText(LifeKind kind, int units) {
    if (kind == LifeKind::Count) {
        return std::to_string(units);
    }
    const int seconds = units * 4;
    const int rest = seconds % 60;
    return std::to_string(seconds / 60) + (rest < 10 ? ":0" : ":") + std::to_string(rest);
}

} // namespace m350::tools
