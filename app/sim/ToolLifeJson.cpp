#include "app/sim/ToolLifeJson.h"

#include "core/tools/ToolLifeView.h"

namespace m350::sim {

nlohmann::json toolLifeJson(const tools::ToolLifeManager& manager, const std::vector<tools::LifeFileIssue>& issues) {
    const tools::LifeView view = tools::makeLifeView(manager);
    nlohmann::json groups = nlohmann::json::array();
    for (const tools::LifeGroupView& g : view.groups) {
        nlohmann::json tools = nlohmann::json::array();
        for (const tools::LifeToolView& t : g.tools) {
            tools.push_back({{"tool", t.tool},
                             {"h", t.h},
                             {"d", t.d},
                             {"used", t.used},
                             {"remaining", t.remaining},
                             {"expired", t.expired},
                             {"in_use", t.inUse}});
        }
        groups.push_back({{"group", g.number},
                          {"kind", g.kind == tools::LifeKind::Count ? "count" : "minutes"},
                          {"life", g.life},
                          {"life_units", g.lifeUnits},
                          {"tools", tools}});
    }
    nlohmann::json inUse = nullptr;
    if (view.inUse) {
        inUse = {{"group", view.inUse->group}, {"tool", view.inUse->tool}};
    }
    nlohmann::json issueList = nlohmann::json::array();
    for (const tools::LifeFileIssue& issue : issues) {
        issueList.push_back({{"severity", "error"},
                             {"file", issue.file},
                             {"line", issue.line},
                             {"column", issue.column},
                             {"message", issue.message}});
        if (!issue.words.id.empty()) {
            issueList.back()["message_id"] = issue.words.id;
        }
    }
    return {{"ignore", view.ignoreNumber},
            {"gs", view.gs},
            {"in_use", inUse},
            {"groups", groups},
            {"issues", issueList},
            {"tool_change_signal", manager.toolChangeSignal()},
            {"new_tool_signal", manager.newToolSignal()}};
}

} // namespace m350::sim
