#include "core/tools/ToolLifeManager.h"

#include "core/common/Message.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace m350::tools {

namespace {

constexpr double kUnitSeconds = 4.0; // cutting time counts in 4 s units

std::string usedText(const LifeGroup& g, const LifeTool& t) {
    return "T" + std::to_string(t.tool) + " " + std::to_string(t.used) + "/" + std::to_string(g.lifeUnits());
}

} // namespace

void ToolLifeManager::setData(LifeData data) {
    data_ = std::move(data);
    changed_ = false;
    ++revision_;
    countedTools_.clear();
    selected_.reset();
    active_.reset();
    entry_.reset();
}

void ToolLifeManager::startRun() {
    countedTools_.clear();
    entry_.reset(); // a G10 L3 without G11 enters nothing
}

const LifeTool* ToolLifeManager::findTool(const InUse& at) const {
    const LifeGroup* group = data_.group(at.group);
    if (!group) {
        return nullptr;
    }
    auto it = std::find_if(group->tools.begin(), group->tools.end(), [&](const LifeTool& t) { return t.tool == at.tool; });
    return it == group->tools.end() ? nullptr : &*it;
}

LifeTool* ToolLifeManager::findTool(const InUse& at) {
    return const_cast<LifeTool*>(static_cast<const ToolLifeManager*>(this)->findTool(at));
}

ToolLifeManager::Selection ToolLifeManager::selectGroup(int t) {
    const int number = t - data_.ignoreNumber;
    const LifeGroup* group = data_.group(number);
    if (!group) {
        return {0, message("tool_life_group_missing",
                           {std::to_string(t), std::to_string(number), std::to_string(data_.ignoreNumber)})};
    }
    ++revision_;
    if (auto counted = countedTools_.find(number); counted != countedTools_.end() && group->kind == LifeKind::Count) {
        selected_ = InUse{number, counted->second}; // counted once this run: the same tool, no new one
        newTool_ = false;
        return {counted->second, std::nullopt};
    }
    for (std::size_t i = 0; i < group->tools.size(); ++i) {
        const LifeTool& tool = group->tools[i];
        if (!group->expired(tool)) {
            selected_ = InUse{number, tool.tool};
            newTool_ = i > 0 && tool.used == 0; // a sister tool takes over from an expired one
            return {tool.tool, std::nullopt};
        }
    }
    // FANUC: with every tool expired the last one goes on, and the tool change signal tells the PMC
    const LifeTool& last = group->tools.back();
    selected_ = InUse{number, last.tool};
    newTool_ = false;
    std::string list;
    for (const LifeTool& tool : group->tools) {
        list += (list.empty() ? "" : ", ") + usedText(*group, tool);
    }
    notice_ = message(group->kind == LifeKind::Count ? "tool_life_expired_count" : "tool_life_expired_time",
                      {std::to_string(number), list, std::to_string(last.tool)});
    return {last.tool, std::nullopt};
}

bool ToolLifeManager::toolChangeSignal() const {
    return std::any_of(data_.groups.begin(), data_.groups.end(), [](const LifeGroup& g) {
        return !g.tools.empty() &&
               std::all_of(g.tools.begin(), g.tools.end(), [&g](const LifeTool& t) { return g.expired(t); });
    });
}

void ToolLifeManager::changeTool(bool count) {
    beforeChange_ = BeforeChange{active_, useSeconds_, usedBefore_, lastCutStart_, lastCutEnd_, std::nullopt};
    active_ = selected_;
    ++revision_;
    useSeconds_ = 0.0;
    lastCutEnd_ = lastCutStart_ = 0.0;
    if (!active_) {
        return;
    }
    LifeTool* tool = findTool(*active_);
    const LifeGroup* group = data_.group(active_->group);
    if (!tool || !group) {
        active_.reset();
        return;
    }
    usedBefore_ = tool->used;
    if (count && group->kind == LifeKind::Count && countedTools_.emplace(group->number, tool->tool).second) {
        ++tool->used;
        beforeChange_->counted = active_;
        dataChanged();
    }
}

void ToolLifeManager::revertChange() {
    if (!beforeChange_) {
        return;
    }
    BeforeChange before = *std::exchange(beforeChange_, std::nullopt);
    if (before.counted) {
        if (LifeTool* tool = findTool(*before.counted)) {
            --tool->used;
            dataChanged();
        }
        countedTools_.erase(before.counted->group);
    }
    active_ = before.active;
    useSeconds_ = before.useSeconds;
    usedBefore_ = before.usedBefore;
    lastCutStart_ = before.lastCutStart;
    lastCutEnd_ = before.lastCutEnd;
    ++revision_;
}

void ToolLifeManager::recount() {
    LifeTool* tool = active_ ? findTool(*active_) : nullptr;
    const LifeGroup* group = active_ ? data_.group(active_->group) : nullptr;
    if (!tool || !group || group->kind != LifeKind::Minutes) {
        return;
    }
    int used = usedBefore_ + static_cast<int>(std::floor(useSeconds_ / kUnitSeconds + 1e-9));
    if (used != tool->used) {
        tool->used = used;
        dataChanged();
    }
}

void ToolLifeManager::cut(double start, double end) {
    const LifeGroup* group = active_ ? data_.group(active_->group) : nullptr;
    if (!group || group->kind != LifeKind::Minutes || end <= start) {
        return;
    }
    useSeconds_ += end - start;
    lastCutStart_ = start;
    lastCutEnd_ = end;
    recount();
}

void ToolLifeManager::cutShortAt(double t) {
    if (lastCutEnd_ > t) {
        useSeconds_ = std::max(0.0, useSeconds_ - (lastCutEnd_ - std::max(t, lastCutStart_)));
        lastCutEnd_ = std::max(t, lastCutStart_);
        recount();
    }
}

std::optional<Message> ToolLifeManager::resetGroup(int number) {
    LifeGroup* group = data_.group(number);
    if (!group) {
        return message("tool_life_reset_missing", {std::to_string(number)});
    }
    for (LifeTool& tool : group->tools) {
        tool.used = 0;
    }
    countedTools_.erase(number); // a count group's next selection in this run counts again
    if (active_ && active_->group == number) {
        usedBefore_ = 0;
        useSeconds_ = 0.0;
        lastCutEnd_ = lastCutStart_ = 0.0;
    }
    dataChanged();
    return std::nullopt;
}

std::variant<int, Message> ToolLifeManager::offsetOfToolInUse(char letter) const {
    const LifeTool* tool = active_ ? findTool(*active_) : nullptr;
    if (!tool) {
        return message("tool_life_offset_none", {std::string(1, letter), std::to_string(data_.ignoreNumber + 1)});
    }
    return letter == 'H' ? tool->h : tool->d;
}

} // namespace m350::tools
