#pragma once

#include "core/macro/Value.h"
#include "core/macro/VariableMap.h"

#include <optional>
#include <string>
#include <string_view>

namespace m350::macro {

// The variables that belong to the machine rather than to the macro interpreter: positions, work
// offsets, IO, homed flags, messages, modal state. The controller implements this; the executor
// never reaches the machine any other way.
class MachineAccess {
public:
    virtual ~MachineAccess() = default;

    virtual Value readSystem(const VariableInfo& info, int number) = 0;

    // `text` is the comment written after the value (`#1503 = 1(text)`), already formatted.
    // Returns a message when the machine refuses the write; the executor raises it as an alarm.
    virtual std::optional<std::string> writeSystem(const VariableInfo& info, int number, double value,
                                                   std::string_view text) = 0;
};

} // namespace m350::macro
