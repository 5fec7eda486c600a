#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace m350::tools {

// FANUC 0i tool life management data: groups of interchangeable (sister) tools, each with a life
// by count or by minutes, used in the order given.
enum class LifeKind : std::uint8_t { Count, Minutes };

struct LifeTool {
    int tool = 0;   // T number (up to 4 digits)
    int h = 0;      // its length offset number (H99 selects it), 0 = none
    int d = 0;      // its radius offset number (D99 selects it), 0 = none
    int used = 0;   // uses (count groups) or cutting time in 4 s units (minute groups)
};

struct LifeGroup {
    int number = 0;
    int life = 0; // uses, or minutes
    LifeKind kind = LifeKind::Count;
    std::vector<LifeTool> tools; // in use order

    // The life in the unit `used` counts: uses, or 4 s units (15 per minute).
    int lifeUnits() const { return kind == LifeKind::Count ? life : life * 15; }
    bool expired(const LifeTool& t) const { return t.used >= lifeUnits(); }
};

// How many groups of how many tools the memory holds, by parameter 6800 GS1 (#0) and GS2 (#1), as
// the 0i seed's table gives it: neither -> 16 x 16, GS2 -> 32 x 8, GS1 -> 64 x 4, both -> 128 x 2.
struct LifeCapacity {
    int groups = 16;
    int toolsPerGroup = 16;
};
LifeCapacity lifeCapacity(int gs); // gs = GS2 * 2 + GS1 (6800's bits 0 and 1), 0..3

struct LifeData {
    int gs = 0;                 // GS2 * 2 + GS1 (parameter 6800 #0, #1)
    int ignoreNumber = 100;     // parameter 6810: T101 = group 1
    LifeKind defaultKind = LifeKind::Count; // parameter 6800 #2 LTM: the kind when G10 L3 gives no Q
    bool extendedEntry = true;  // parameter 6801 #6 EXT: G10 L3 P1 / P2 (add, change, delete) allowed
    // On a FANUC machine these settings are its parameters (6800, 6801, 6810 in params.toml) and
    // toollife.txt holds only the groups; on the M350 (a simulator extra) the file holds them too.
    bool fromParameters = false;
    std::vector<LifeGroup> groups; // by ascending number
    // Lines of toollife.txt the reader skipped, as they were: kept so that saving loses nothing.
    std::vector<std::string> unreadLines;

    LifeGroup* group(int number);
    const LifeGroup* group(int number) const;
    // Puts a group in (replacing one with its number), keeping the groups sorted.
    void putGroup(LifeGroup group);
    bool removeGroup(int number);
    // Why the group does not fit the capacity of `gs`, if it does not.
    std::optional<Message> capacityProblem(const LifeGroup& group) const;
    // Takes the settings from a FANUC control's parameters: 6800 (#0 GS1, #1 GS2, #2 LTM), 6801
    // (#6 EXT), 6810 (the ignore number); a parameter the machine does not set has its default.
    void applyFanucParameters(const std::map<int, double>& parameters);
};

} // namespace m350::tools
