#pragma once

#include "core/common/Message.h"
#include "core/gcode/Dialect.h"

#include <optional>
#include <string>
#include <vector>

namespace m350::macro {

// A run of variable numbers, both ends included.
struct VariableRange {
    int first = 0;
    int last = 0;
    bool operator==(const VariableRange&) const = default;
};

// What a machine's control has of the variables that FANUC sells as options: the common variables
// (machine.toml [variables] common) and the additional work coordinate systems G54.1 P1-Pn
// ([coordinates] additional_systems), whose offsets are variables too (#7001-#7948, #14001-...).
// Left unset, a machine has its dialect's: FANUC 0i #100-#199 and #500-#999 with 48 systems, the
// M350 its fixed map and none.
struct VariableLayout {
    std::vector<VariableRange> common; // empty: the dialect's
    int additionalWorkSystems = -1;    // -1: the dialect's

    static constexpr int kMostWorkSystems = 300; // the 30i's G54.1 P1-P300
    static constexpr int kLastVariable = 999999; // six digits, the 30i's largest variable numbers

    std::vector<VariableRange> commonRanges(const gcode::Dialect& dialect) const;
    int workSystems(const gcode::Dialect& dialect) const;

    // Why `ranges` cannot be a FANUC machine's common variables: outside #100-#999 and
    // #20000-#999999 (the system variables lie between), or overlapping one another.
    static std::optional<Message> refusedCommon(const std::vector<VariableRange>& ranges);
};

} // namespace m350::macro
