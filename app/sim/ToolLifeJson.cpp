#include "app/sim/ToolLifeJson.h"

namespace m350::sim {

nlohmann::json toolLifeJson(const tools::ToolLifeManager& manager) {
    const tools::LifeData& data = manager.data();
    nlohmann::json groups = nlohmann::json::array();
    for (const tools::LifeGroup& g : data.groups) {
        nlohmann::json tools = nlohmann::json::array();
        for (const tools::LifeTool& t : g.tools) {
            tools.push_back({{"tool", t.tool}, {"h", t.h}, {"d", t.d}, {"used", t.used}, {"expired", g.expired(t)}});
        }
        groups.push_back({{"group", g.number},
                          {"kind", g.kind == tools::LifeKind::Count ? "count" : "minutes"},
                          {"life", g.life},
                          {"life_units", g.lifeUnits()},
                          {"tools", tools}});
    }
    nlohmann::json inUse = nullptr;
    if (auto active = manager.inUse()) {
        inUse = {{"group", active->group}, {"tool", active->tool}};
    }
    return {{"ignore", data.ignoreNumber}, {"gs", data.gs}, {"in_use", inUse}, {"groups", groups}};
}

} // namespace m350::sim
