#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/BlockStorage.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/LineSplitter.h"

#include <string_view>

namespace m350::gcode {

enum class PlainResult { Declined, Empty, Parsed };

// The fast path for the lines that make up most programs: address words with plain numbers
// (`N10 G1 X12.5 Y-3 F1000 (rough)`), read straight from the characters. Anything else (macro
// syntax, keywords, malformed numbers, O lines, block delete) is Declined and left to the general
// BlockParser, which gives the same result for every line this accepts (tested). `out` is written
// only when the line is Parsed (all of it: it may be raw memory).
PlainResult parsePlainBlock(std::string_view line, const Dialect& dialect, SourceLocation location,
                            BlockStorage& storage, Block& out, LineEnd lineEnd = LineEnd::Unknown);

// The same for the line that starts at `text` and ends at the first '\n' or '\r', which the
// caller knows to come before the text ends: the line is read in place, without first looking
// for its end, and `length` says where it ended (set unless Declined).
PlainResult parsePlainLine(const char* text, const Dialect& dialect, SourceLocation location, BlockStorage& storage,
                           Block& out, std::size_t& length);

} // namespace m350::gcode
