#pragma once

#include "core/tools/ToolLifeData.h"

#include <cstdint>
#include <optional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <variant>

namespace m350::tools {

// FANUC 0i tool life management, as the 0i manual's T function chapter gives it:
// - `T<ignore + n>` selects group n: its first tool, in the order entered, whose life is not over;
//   a T below the ignore number is an ordinary tool. When every tool of the group is expired the
//   control goes on with the group's last tool and raises the tool change signal (TLCH).
// - The PMC signals (FANUC F064): TLCH (#0) while a group has no tool left, TLNW (#1) from the T
//   command that selected a new tool of a group (a sister tool starting its life) to the next T.
// - The tool change (M06; on the M350, where T itself changes the tool, the T word) ends the life
//   counting of the tool in use and starts it for the selected one.
// - Count groups: a tool's use counts once per run (from reset into automatic operation), however
//   often the program names its group; the group keeps that tool for the rest of the run.
// - Minute groups: the tool in use gathers cutting time (feed moves and arcs; no rapids, dwells,
//   holds), counted in whole 4 s units per use: under 4 s is not counted.
// - H99 / D99 take the H / D entered for the tool in use.
// - G10 L3 (clear everything, then enter), G10 L3 P1 (add or change groups), G10 L3 P2 (delete
//   groups): the blocks up to G11 are the data; they take effect at G11.
// Errors are returned as text; the caller raises them as alarms where the program stands.
class ToolLifeManager {
public:
    void setData(LifeData data);
    // A FANUC control's settings from its parameters (LifeData::applyFanucParameters), the groups kept.
    void applyFanucParameters(const std::map<int, double>& parameters) {
        data_.applyFanucParameters(parameters);
        ++revision_;
    }
    const LifeData& data() const { return data_; }
    // Management is on while there is at least one group.
    bool enabled() const { return !data_.groups.empty(); }
    // Whether the life data changed since setData / markSaved (to be written to the machine folder).
    bool changed() const { return changed_; }
    void markSaved() { changed_ = false; }
    // Goes up whenever the data, the selection or the tool in use change (the panel redraws then).
    std::uint64_t revision() const { return revision_; }

    // The operator's tool life reset (counter clear) of one group: every tool's used life back to
    // 0, the tool in use counting on from there. The reason when there is no such group.
    std::optional<Message> resetGroup(int number);

    // From reset into automatic operation: count groups count again.
    void startRun();

    // Whether a T value names a group (management on and T at or above the ignore number).
    bool isGroupCommand(int t) const { return enabled() && t >= data_.ignoreNumber; }
    // The tool a group command selects; it waits for the tool change. An ordinary T selects no group.
    struct Selection {
        int tool = 0;
        std::optional<Message> refusal; // no such group
    };
    // What the last selection has to tell the operator (every tool of its group expired), once.
    std::optional<Message> takeNotice() { return std::exchange(notice_, std::nullopt); }
    Selection selectGroup(int t);
    void selectOrdinaryTool() {
        selected_.reset();
        newTool_ = false;
        ++revision_;
    }
    // TLCH: a group whose every tool has reached its life (until the operator resets it).
    bool toolChangeSignal() const;
    // TLNW: the last T command selected a new tool of its group.
    bool newToolSignal() const { return newTool_; }
    // The tool change: the selected group's tool becomes the one in use and counts (`count` false
    // while a run is only scanned for 断点加工).
    void changeTool(bool count);
    // The last tool change did not happen (its program alarmed or was stopped): the tool in use is
    // the one before it again, and a use it counted is taken back.
    void revertChange();

    // Cutting feed from `start` to `end` (virtual seconds) with the tool in use.
    void cut(double start, double end);
    // A hold, reset or E-stop stopped the machine at `t`: the cut planned beyond it never happened.
    void cutShortAt(double t);

    struct InUse {
        int group = 0;
        int tool = 0;
    };
    std::optional<InUse> inUse() const { return active_; }
    std::optional<InUse> selected() const { return selected_; }
    // H99 / D99: the offset number entered for the tool in use.
    std::variant<int, Message> offsetOfToolInUse(char letter) const;

    // G10 L3 data entry (ToolLifeEntry.cpp). mode: 0 replace everything, 1 add/change, 2 delete.
    bool entering() const { return entry_.has_value(); }
    std::optional<Message> beginEntry(int mode);
    struct EntryLine {
        std::optional<int> p, l, q, t, h, d;
    };
    std::optional<Message> entryLine(const EntryLine& line);
    std::optional<Message> endEntry(); // G11

private:
    const LifeTool* findTool(const InUse& at) const;
    LifeTool* findTool(const InUse& at);
    void recount();
    void dataChanged() {
        changed_ = true;
        ++revision_;
    }

    LifeData data_;
    bool changed_ = false;
    std::uint64_t revision_ = 0;
    std::map<int, int> countedTools_; // count group -> the tool whose use this run has counted
    std::optional<InUse> selected_;
    std::optional<InUse> active_;
    bool newTool_ = false;
    std::optional<Message> notice_;
    // the use of the tool in use for a minutes group
    double useSeconds_ = 0.0;
    int usedBefore_ = 0;
    double lastCutStart_ = 0.0;
    double lastCutEnd_ = 0.0;
    // What the last changeTool replaced, until the next one.
    struct BeforeChange {
        std::optional<InUse> active;
        double useSeconds = 0.0;
        int usedBefore = 0;
        double lastCutStart = 0.0;
        double lastCutEnd = 0.0;
        std::optional<InUse> counted; // the use it counted
    };
    std::optional<BeforeChange> beforeChange_;

    struct Entry {
        int mode = 0;
        LifeData staged;        // the groups entered so far
        std::set<int> deleted;  // mode 2
        int group = 0;          // the group the T lines go to
    };
    std::optional<Entry> entry_;
};

} // namespace m350::tools
