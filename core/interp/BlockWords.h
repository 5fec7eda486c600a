#pragma once

#include "core/common/Message.h"
#include "core/interp/LetterWords.h"
#include "core/macro/BlockSink.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace m350::interp {

// The words of one block by letter, as the executor indexed them (EvaluatedBlock, which
// outlives execute()). `present` holds the letters other than G and M.
struct BlockWords {
    const macro::WordValue* words = nullptr;
    const std::uint32_t* firstOf = nullptr; // EvaluatedBlock::firstOf
    std::uint32_t present = 0;
    LetterWords g;
    LetterWords m;
    // Bit c: a G word within 1e-6 of the whole code c (0-127), so hasG() of a whole code is one
    // test; moveAxes asks about a dozen codes for every block.
    std::array<std::uint64_t, 2> gCodes{};

    void reset(const macro::EvaluatedBlock& evaluated) {
        words = evaluated.words.data();
        firstOf = evaluated.firstOf.data();
        present = evaluated.letters & ~(bit('G') | bit('M'));
        g = LetterWords(evaluated, 'G', evaluated.gCount);
        m = LetterWords(evaluated, 'M', evaluated.mCount);
        if (!evaluated.otherCodes) {
            gCodes = evaluated.gCodes.bits; // every G word a whole code 0-127 exactly
            return;
        }
        gCodes = {};
        for (const macro::WordValue& w : g) {
            if (w.value > -0.5 && w.value < 127.5) {
                const auto code = static_cast<unsigned>(w.value + 0.5); // the nearest whole code
                if (std::abs(w.value - code) < 1e-6) {
                    gCodes[code >> 6] |= std::uint64_t{1} << (code & 63u);
                }
            }
        }
    }
    static constexpr std::uint32_t bit(char c) { return 1u << static_cast<unsigned>(c - 'A'); }
    bool has(char c) const { return (present & bit(c)) != 0; }
    const macro::WordValue& operator[](char c) const { return words[firstOf[static_cast<std::size_t>(c - 'A')]]; }
    const macro::WordValue* find(char c) const { return has(c) ? &(*this)[c] : nullptr; }
    bool hasG(int code) const {
        if (code >= 0 && code < 128) {
            return (gCodes[static_cast<unsigned>(code) >> 6] >> (static_cast<unsigned>(code) & 63u) & 1u) != 0;
        }
        for (const macro::WordValue& w : g) {
            if (std::abs(w.value - code) < 1e-6) {
                return true;
            }
        }
        return false;
    }
    // Whether any of `codes` (bits as gCodes holds them) was written.
    bool hasAnyG(const std::array<std::uint64_t, 2>& codes) const {
        return ((gCodes[0] & codes[0]) | (gCodes[1] & codes[1])) != 0;
    }
    bool hasAxis() const {
        return (present & (bit('X') | bit('Y') | bit('Z') | bit('A') | bit('B'))) != 0;
    }
};

// "G5.1", "X-1.5": a word as the interpreter's messages name it (their %1).
std::string wordText(const macro::WordValue& w);
// The block's alarm at `w`: an invalid word, said by `words`.
[[noreturn]] void invalidWord(const macro::WordValue& w, const Message& words);

} // namespace m350::interp
