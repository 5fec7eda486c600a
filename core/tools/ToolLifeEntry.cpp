// G10 L3 tool life data entry: the blocks between G10 L3 [P1|P2] and G11.
#include "core/tools/ToolLifeManager.h"

#include <algorithm>

namespace m350::tools {

std::optional<Message> ToolLifeManager::beginEntry(int mode) {
    if (entry_) {
        return message("tool_life_entry_open");
    }
    if (mode < 0 || mode > 2) {
        return message("tool_life_entry_mode", {std::to_string(mode)});
    }
    if (mode != 0 && !data_.extendedEntry) {
        return message("tool_life_entry_extended",
                       {std::to_string(mode), mode == 1 ? bilingual("add or change", "添加或修改") : bilingual("delete", "删除")});
    }
    Entry entry;
    entry.mode = mode;
    entry.staged.gs = data_.gs;
    entry.staged.ignoreNumber = data_.ignoreNumber;
    entry.staged.defaultKind = data_.defaultKind;
    entry_ = std::move(entry);
    return std::nullopt;
}

std::optional<Message> ToolLifeManager::entryLine(const EntryLine& line) {
    Entry& e = *entry_;
    const LifeCapacity capacity = lifeCapacity(e.staged.gs);
    if (line.p) {
        if (line.t || line.h || line.d) {
            return message("tool_life_entry_group_and_tool");
        }
        if (*line.p < 1 || *line.p > capacity.groups) {
            return message("tool_life_entry_group_beyond", {std::to_string(*line.p), std::to_string(capacity.groups)});
        }
        if (e.mode == 2) {
            if (line.l || line.q) {
                return message("tool_life_delete_only_p");
            }
            if (!data_.group(*line.p)) {
                return message("tool_life_delete_missing", {std::to_string(*line.p)});
            }
            e.deleted.insert(*line.p);
            return std::nullopt;
        }
        if (!line.l || *line.l < 1) {
            return message("tool_life_entry_needs_life", {std::to_string(*line.p)});
        }
        if (line.q && *line.q != 1 && *line.q != 2) {
            return message("tool_life_entry_q");
        }
        if (e.staged.group(*line.p)) {
            return message("tool_life_entry_twice", {std::to_string(*line.p)});
        }
        LifeGroup group;
        group.number = *line.p;
        group.life = *line.l;
        group.kind = line.q ? (*line.q == 1 ? LifeKind::Count : LifeKind::Minutes) : data_.defaultKind;
        e.staged.putGroup(group);
        e.group = group.number;
        return std::nullopt;
    }
    if (line.t) {
        LifeGroup* group = e.staged.group(e.group);
        if (!group || e.mode == 2) {
            return message("tool_life_entry_tool_first");
        }
        if (*line.t < 1 || *line.t > 9999 || line.h.value_or(0) < 0 || line.d.value_or(0) < 0 ||
            line.h.value_or(0) > 999 || line.d.value_or(0) > 999) {
            return message("tool_life_entry_ranges");
        }
        if (static_cast<int>(group->tools.size()) >= capacity.toolsPerGroup) {
            return message("tool_life_entry_group_full",
                           {std::to_string(group->number), std::to_string(capacity.toolsPerGroup)});
        }
        LifeTool tool;
        tool.tool = *line.t;
        tool.h = line.h.value_or(0);
        tool.d = line.d.value_or(0);
        if (const LifeGroup* old = data_.group(group->number); old && e.mode == 1) {
            auto same = std::find_if(old->tools.begin(), old->tools.end(), [&](const LifeTool& t) { return t.tool == tool.tool; });
            tool.used = same == old->tools.end() ? 0 : same->used; // a changed group keeps what its tools used
        }
        group->tools.push_back(tool);
        return std::nullopt;
    }
    return message("tool_life_entry_block");
}

std::optional<Message> ToolLifeManager::endEntry() {
    if (!entry_) {
        return message("tool_life_g11_no_entry");
    }
    Entry e = std::move(*entry_);
    entry_.reset();
    for (const LifeGroup& g : e.staged.groups) {
        if (g.tools.empty()) {
            return message("tool_life_entry_no_tools", {std::to_string(g.number)});
        }
    }
    if (e.mode == 0) {
        data_.groups = std::move(e.staged.groups);
    } else if (e.mode == 1) {
        for (LifeGroup& g : e.staged.groups) {
            data_.putGroup(std::move(g));
        }
    } else {
        for (int number : e.deleted) {
            data_.removeGroup(number);
        }
    }
    dataChanged();
    countedTools_.clear();
    if (active_ && !findTool(*active_)) {
        active_.reset();
    } else if (active_) {
        usedBefore_ = findTool(*active_)->used; // the tool in use counts on from what was entered
        useSeconds_ = 0.0;
    }
    if (selected_ && !findTool(*selected_)) {
        selected_.reset();
    }
    return std::nullopt;
}

} // namespace m350::tools
