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

} // namespace m350::tools
