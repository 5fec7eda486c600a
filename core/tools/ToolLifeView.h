#pragma once

#include "core/tools/ToolLifeManager.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::tools {

// Tool life management as the operator's screen shows it (the panel's 刀具寿命 view, m350-sim's
// "tool_life"): each group with its tools in use order, the life, what each tool used and has
// left, and which tool is in use. Everything the screen needs is computed here.
struct LifeToolView {
    int tool = 0;
    int h = 0;
    int d = 0;
    int used = 0;      // uses, or 4 s units
    int remaining = 0; // life - used, never below 0
    bool inUse = false;   // the group's tool on the spindle (FANUC marks it @)
    bool expired = false; // its life is over: selection skips it (FANUC marks it #)
    bool selected = false; // a T command chose it and the tool change has not come yet
};

struct LifeGroupView {
    int number = 0;
    LifeKind kind = LifeKind::Count;
    int life = 0;      // uses, or minutes
    int lifeUnits = 0; // uses, or 4 s units
    bool allExpired = false; // its last tool goes on and TLCH is raised
    std::vector<LifeToolView> tools;
};

struct LifeView {
    int ignoreNumber = 100;
    int gs = 0;
    LifeCapacity capacity;
    std::optional<ToolLifeManager::InUse> inUse;
    std::vector<LifeGroupView> groups;
    int unreadLines = 0; // lines of toollife.txt the reader skipped (kept in the file as comments)
};

LifeView makeLifeView(const ToolLifeManager& manager);

// An amount of life as the screen writes it: uses as a number; minutes groups' 4 s units as
// minutes and seconds ("1:32" for 23 units).
std::string lifeAmountText(LifeKind kind, int units);

} // namespace m350::tools
