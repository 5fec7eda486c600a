#pragma once

#include "core/gcode/Block.h"

namespace m350::gcode {

// What the passes over a file need of a block's words, found in one pass over them: whether it
// calls an O program (M98 or G65 with a P number) and what ends the code before it (M30 M2 M99).
struct WordFacts {
    bool call = false;
    const char* ends = nullptr;
};

inline WordFacts wordFacts(const Block& block) {
    WordFacts facts;
    for (const Word& w : block.words) {
        if ((w.letter != 'M' && w.letter != 'G') || !w.isNumber()) { // most words: the cheapest test first
            continue;
        }
        if (w.letter == 'M') {
            if (w.number == 98) {
                facts.call = true;
            } else if (w.number == 30 || w.number == 2 || w.number == 99) {
                facts.ends = w.number == 30 ? "M30" : w.number == 2 ? "M2" : "M99";
            }
        } else if (w.letter == 'G' && w.number == 65) {
            facts.call = true;
        }
    }
    return facts;
}

} // namespace m350::gcode
