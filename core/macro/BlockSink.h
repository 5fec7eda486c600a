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

// Whole G or M codes 0-127 as bits, so a block's codes meet a set of codes in two tests.
struct CodeBits {
    static constexpr int kCodes = 128;
    std::array<std::uint64_t, 2> bits{};

    void add(int code) { bits[static_cast<unsigned>(code) >> 6] |= std::uint64_t{1} << (static_cast<unsigned>(code) & 63u); }
    bool has(int code) const { return (bits[static_cast<unsigned>(code) >> 6] >> (static_cast<unsigned>(code) & 63u) & 1u) != 0; }
    bool meets(const CodeBits& other) const {
        return ((bits[0] & other.bits[0]) | (bits[1] & other.bits[1])) != 0;
    }
};

// A block after macro evaluation: every word a plain number, calls and their arguments removed.
// `letters` and the code bits describe the words as evaluated, before calls are taken out: what
// lets a plain block pass the tool life and call checks without a scan of its words.
struct EvaluatedBlock {
    const gcode::Block* source = nullptr;
    std::vector<WordValue> words;
    std::uint32_t letters = 0; // bit (letter - 'A') for each letter written
    CodeBits gCodes;           // G words of exactly a whole code 0-127
    CodeBits mCodes;           // M words the same
    bool otherCodes = false;   // a G or M word that is neither (G65.1, M1000, G-1)

    static constexpr std::uint32_t letterBit(char letter) { return 1u << static_cast<unsigned>(letter - 'A'); }
    bool has(char letter) const { return (letters & letterBit(letter)) != 0; }

    void clear(const gcode::Block& block) {
        source = &block;
        words.clear();
        letters = 0;
        gCodes = {};
        mCodes = {};
        otherCodes = false;
    }
    void add(char letter, double value, std::uint32_t column) {
        words.push_back({letter, value, column});
        letters |= letterBit(letter);
        if (letter == 'G' || letter == 'M') {
            if (value >= 0 && value < CodeBits::kCodes && value == static_cast<double>(static_cast<int>(value))) {
                (letter == 'G' ? gCodes : mCodes).add(static_cast<int>(value));
            } else {
                otherCodes = true;
            }
        }
    }
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
