#pragma once

#include "core/gcode/Block.h"
#include "core/macro/MacroError.h"

#include <cstdint>
#include <array>
#include <optional>
#include <vector>

namespace m350::macro {

struct WordValue {
    char letter = 0;
    double value = 0.0;
    std::uint32_t column = 0;
};

// A block after macro evaluation: every word a plain number, calls and their arguments removed.
struct EvaluatedBlock {
    const gcode::Block* source = nullptr;
    std::vector<WordValue> words;
};

struct BlockOutcome {
    bool endProgram = false;             // M30 / M02
    std::optional<MacroError> error;     // an invalid code or value: the executor raises the alarm
};

// The modal G-code interpreter, as the executor sees it: it receives the words of each ordinary
// block, in program order.
class BlockSink {
public:
    virtual ~BlockSink() = default;
    virtual BlockOutcome execute(const EvaluatedBlock& block) = 0;

    // Where the program stands, for canned-cycle handler programs (the M350's O9081 ...): the work
    // position of X Y Z A B, whether distances are incremental (G91), whether cycles return to R
    // (G99) rather than to the initial level (G98).
    struct CycleContext {
        std::array<double, 5> work{};
        bool incremental = false;
        bool returnToR = false;
    };
    virtual CycleContext cycleContext() const { return {}; }
};

} // namespace m350::macro
