#pragma once

#include "core/gcode/Arena.h"
#include "core/gcode/Block.h"
#include "core/gcode/Expression.h"

#include <span>
#include <vector>

namespace m350::gcode {

// Where parsed blocks keep what they refer to: expression trees, words, assignments and text.
// Blocks hold only indexes, spans and views into it, so a Block is trivially copyable and a
// program of 200,000 blocks is freed in a few hundred deallocations.
struct BlockStorage {
    ExpressionPool expressions;
    Arena<Word> words;
    Arena<Assignment> assignments;
    TextArena text;
    // The items of the DPRNT, BPRNT and Modbus statements, by Block::statement (few blocks have
    // any, so a block holds an index instead of a span).
    Arena<StatementItem> statementItems;
    std::vector<std::span<const StatementItem>> statements;
};

} // namespace m350::gcode
