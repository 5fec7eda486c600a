#pragma once

#include "core/gcode/Block.h"
#include "core/macro/MacroError.h"

#include <cstdint>
#include <array>
#include <optional>
#include <span>
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

// What a block's words are, letter by letter: see EvaluatedBlock.
struct WordSummary {
    std::uint32_t letters = 0; // bit (letter - 'A') for each letter written
    CodeBits gCodes;           // G words of exactly a whole code 0-127
    CodeBits mCodes;           // M words the same
    bool otherCodes = false;   // a G or M word that is neither (G65.1, M1000, G-1)
    std::int64_t repeated = -1; // the first word that writes a letter other than G and M again (-1: none)
    std::uint32_t gCount = 0;   // how many G words
    std::uint32_t mCount = 0;

    static constexpr std::uint32_t letterBit(char letter) { return 1u << static_cast<unsigned>(letter - 'A'); }
    bool has(char letter) const { return (letters & letterBit(letter)) != 0; }

    // Takes in word `at`; the first word of each letter other than G and M goes to `firstOf`.
    void note(std::array<std::uint32_t, 26>& firstOf, char letter, double value, std::size_t at) {
        const std::uint32_t bit = letterBit(letter);
        if ((bit & (letterBit('G') | letterBit('M'))) != 0) {
            ++(letter == 'G' ? gCount : mCount);
            if (value >= 0 && value < CodeBits::kCodes && value == static_cast<double>(static_cast<int>(value))) {
                (letter == 'G' ? gCodes : mCodes).add(static_cast<int>(value));
            } else {
                otherCodes = true;
            }
        } else if ((letters & bit) == 0) {
            firstOf[static_cast<std::size_t>(letter - 'A')] = static_cast<std::uint32_t>(at);
        } else if (repeated < 0) {
            repeated = static_cast<std::int64_t>(at);
        }
        letters |= bit;
    }
};

// A block after macro evaluation: every word a plain number, calls and their arguments removed.
// `letters` and the code bits describe the words: what lets a plain block pass the tool life and
// call checks without a scan of its words. The same pass indexes the words by letter for the modal
// interpreter, so it does not sort them again: whoever takes words out (the call planning) calls
// reindex() before handing the block on.
struct EvaluatedBlock : WordSummary {
    const gcode::Block* source = nullptr;
    std::vector<WordValue> words;
    // Where the first word of each letter other than G and M stands (for the letters written).
    std::array<std::uint32_t, 26> firstOf{};

    void clear(const gcode::Block& block) {
        source = &block;
        words.clear();
        summary() = {};
    }
    void add(char letter, double value, std::uint32_t column) {
        const std::size_t at = words.size();
        words.push_back({letter, value, column});
        summary().note(firstOf, letter, value, at);
    }
    // The words of a block whose words are all plain numbers (most blocks), in one pass; false
    // (and the words unfinished) at a word that is an expression. The summary is kept apart until
    // the end: each word written (a char, which may alias anything) would otherwise have it read
    // back from memory.
    bool assignNumbers(const gcode::Block& block) {
        source = &block;
        const std::span<const gcode::Word> in = block.words;
        words.resize(in.size());
        WordValue* out = words.data();
        WordSummary kept;
        for (std::size_t i = 0; i < in.size(); ++i) {
            const gcode::Word& w = in[i];
            if (!w.isNumber()) {
                return false;
            }
            out[i] = {w.letter, w.number, w.column};
            kept.note(firstOf, w.letter, w.number, i);
        }
        summary() = kept;
        return true;
    }
    void reindex() {
        WordSummary kept;
        for (std::size_t i = 0; i < words.size(); ++i) {
            kept.note(firstOf, words[i].letter, words[i].value, i);
        }
        summary() = kept;
    }

private:
    WordSummary& summary() { return *this; }
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
