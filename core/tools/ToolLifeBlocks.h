#pragma once

#include "core/macro/BlockSink.h"
#include "core/tools/ToolLifeManager.h"


namespace m350::tools {

// Where tool life management meets the program (the words of one block, before the executor takes
// its calls out): G10 L3 .. G11 data blocks are taken whole; a group's T word becomes the tool it
// selects (so the T program or the PMC sees a real tool); H99 / D99 become the tool in use's
// offset numbers; the tool change starts counting. Errors are thrown as macro::MacroError at the
// word's column.
struct ToolLifeBlockContext {
    bool tChangesTool = false; // the M350: T runs the tool change itself; FANUC: M06 does
    bool scanning = false;     // 断点加工's scan: select, but count nothing
};

// True when the block was tool life data and nothing else is to be done with it.
bool applyToolLife(ToolLifeManager& manager, macro::EvaluatedBlock& block, const ToolLifeBlockContext& context);

// Whether applyToolLife() may have anything to do with the block, from its letters and codes alone
// (no T H D G10 G11 M06 and no data being entered: most blocks), asked before its context is made.
inline bool mayConcernToolLife(const ToolLifeManager& manager, const macro::EvaluatedBlock& block) {
    constexpr std::uint32_t kLetters = macro::EvaluatedBlock::letterBit('T') | macro::EvaluatedBlock::letterBit('H') |
                                       macro::EvaluatedBlock::letterBit('D');
    return manager.entering() || (block.letters & kLetters) != 0 || block.otherCodes || block.gCodes.has(10) ||
           block.gCodes.has(11) || block.mCodes.has(6);
}

} // namespace m350::tools
