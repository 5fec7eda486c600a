#pragma once

#include "core/common/Alarm.h"

#include <cstdint>
#include <string>
#include <vector>

namespace m350::macro {

// Raised inside the macro layer while a block executes; the Executor catches it at the block
// boundary and turns it into an Alarm value with file and line.
struct MacroError {
    AlarmCode code;
    std::string message;
    std::uint32_t column = 0;
    // The message's words by id, for the panel to say in its language (Alarm::messageId).
    std::string messageId{};
    std::vector<std::string> messageArguments{};

    static MacroError of(AlarmCode code, const Message& words, std::uint32_t column = 0) {
        return MacroError{code, words.english(), column, words.id, words.arguments};
    }
};

} // namespace m350::macro
