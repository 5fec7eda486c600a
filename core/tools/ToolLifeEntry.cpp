// G10 L3 tool life data entry: the blocks between G10 L3 [P1|P2] and G11.
#include "core/tools/ToolLifeManager.h"

#include <algorithm>

namespace m350::tools {

std::optional<std::string> ToolLifeManager::beginEntry(int mode) {
    if (entry_) {
        return "G10 L3: tool life data entry is already open (end it with G11)";
    }
    if (mode < 0 || mode > 2) {
        return "G10 L3 P" + std::to_string(mode) + ": P1 adds or changes groups, P2 deletes them, no P enters "
                                                  "all data anew";
    }
    if (mode != 0 && !data_.extendedEntry) {
        return "G10 L3 P" + std::to_string(mode) + " (" + (mode == 1 ? "add or change" : "delete") +
               " groups) needs the extended tool life management: parameter 6801 #6 EXT = 1 (6801 = 64 in "
               "params.toml); without it G10 L3 enters all data anew";
    }
    Entry entry;
    entry.mode = mode;
    entry.staged.gs = data_.gs;
    entry.staged.ignoreNumber = data_.ignoreNumber;
    entry.staged.defaultKind = data_.defaultKind;
    entry_ = std::move(entry);
    return std::nullopt;
}

std::optional<std::string> ToolLifeManager::entryLine(const EntryLine& line) {
    Entry& e = *entry_;
    const LifeCapacity capacity = lifeCapacity(e.staged.gs);
    if (line.p) {
        if (line.t || line.h || line.d) {
            return "G10 L3 data: a group (P L Q) and a tool (T H D) go in separate blocks";
        }
        if (*line.p < 1 || *line.p > capacity.groups) {
            return "G10 L3 data: group P" + std::to_string(*line.p) + " is beyond the " +
                   std::to_string(capacity.groups) + " groups the memory holds (GS1/GS2)";
        }
        if (e.mode == 2) {
            if (line.l || line.q) {
                return "G10 L3 P2 (delete): give only the group numbers P";
            }
            if (!data_.group(*line.p)) {
                return "G10 L3 P2: there is no group " + std::to_string(*line.p) + " to delete";
            }
            e.deleted.insert(*line.p);
            return std::nullopt;
        }
        if (!line.l || *line.l < 1) {
            return "G10 L3 data: group P" + std::to_string(*line.p) + " needs its life L (1 or more)";
        }
        if (line.q && *line.q != 1 && *line.q != 2) {
            return "G10 L3 data: Q1 counts uses, Q2 counts minutes";
        }
        if (e.staged.group(*line.p)) {
            return "G10 L3 data: group P" + std::to_string(*line.p) + " is entered twice";
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
            return "G10 L3 data: a tool T needs its group (P_ L_) in a block before it";
        }
        if (*line.t < 1 || *line.t > 9999 || line.h.value_or(0) < 0 || line.d.value_or(0) < 0 ||
            line.h.value_or(0) > 999 || line.d.value_or(0) > 999) {
            return "G10 L3 data: T takes 1-9999, H and D 0-999";
        }
        if (static_cast<int>(group->tools.size()) >= capacity.toolsPerGroup) {
            return "G10 L3 data: group " + std::to_string(group->number) + " holds at most " +
                   std::to_string(capacity.toolsPerGroup) + " tools (GS1/GS2)";
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
    return "G10 L3 data: a block is a group (P L [Q]) or one of its tools (T [H] [D]); end with G11";
}

std::optional<std::string> ToolLifeManager::endEntry() {
    if (!entry_) {
        return "G11 without G10 L3";
    }
    Entry e = std::move(*entry_);
    entry_.reset();
    for (const LifeGroup& g : e.staged.groups) {
        if (g.tools.empty()) {
            return "G10 L3 data: group " + std::to_string(g.number) + " has no tools";
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
