#pragma once

#include "core/common/Alarm.h"

#include <cstdint>
#include <string>

namespace m350::macro {

// Raised inside the macro layer while a block executes; the Executor catches it at the block
// boundary and turns it into an Alarm value with file and line.
struct MacroError {
    AlarmCode code;
    std::string message;
    std::uint32_t column = 0;
};

} // namespace m350::macro
