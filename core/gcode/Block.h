#pragma once

#include "core/gcode/Diagnostic.h"
#include "core/gcode/Expression.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace m350::gcode {

// An address word: `X12.5`, `X-#2`, `G#199`, `P#[1045+#1*3]`. A plain number (most words of most
// programs) is kept in the word itself; anything more is an expression in the program's pool.
struct Word {
    double number = 0.0;    // the value when `value` is kNoExpr
    ExprId value = kNoExpr; // the value's expression, when it is more than a number
    std::uint32_t column : 24 = 0;
    char letter = 0;

    bool isNumber() const { return value == kNoExpr; }
};
static_assert(sizeof(Word) == 16, "a G1 line has four or five words: keep them small");

// Columns past this are stored as this (no line of a real program comes near it).
inline constexpr std::uint32_t kMaxWordColumn = (1u << 24) - 1;
inline std::uint32_t wordColumn(std::uint32_t column) {
    return column < kMaxWordColumn ? column : kMaxWordColumn;
}

// `#index = value`, with the comment that follows it kept as text: `#1503 = 1(T[%.0f])`.
struct Assignment {
    ExprId index = kNoExpr;
    ExprId value = kNoExpr;
    std::string_view text; // stored in the program's TextArena
    bool hasText = false;
    std::uint32_t column = 0;
};

// One item of a DPRNT or BPRNT (a text, or a variable with its digit format), or one argument of
// a Modbus statement (an expression).
struct StatementItem {
    std::string_view text;      // DPRNT/BPRNT text as output (`*` already a space); in the TextArena
    ExprId value = kNoExpr;     // the variable printed, or the argument
    std::uint8_t integerDigits = 0;  // DPRNT #v[cd]: c
    std::uint8_t fractionDigits = 0; // DPRNT #v[cd]: d; BPRNT #v[c]: c
    std::uint32_t column = 0;
};

enum class Control : std::uint8_t {
    None, IfGoto, IfThen, Goto, While, End,
    Popen, Pclos, Dprnt, Bprnt,            // FANUC external output
    MSetData, MGetData, ModbusConversion   // M350 Modbus (MBYTE2DATA and MDATA2BYTE: conversions)
};

// The largest N label and GOTO target: 8 digits, FANUC's longest sequence numbers. Larger ones are
// refused, never rounded into another label.
inline constexpr std::int32_t kMaxLabel = 99999999;

// loopId of a WHILE or END line too damaged to say which loop it is.
inline constexpr std::int32_t kUnknownLoop = -1;

// One line of a program. Control statements stand alone after the N label; ordinary blocks hold
// assignments and words, executed as one unit.
struct Block {
    SourceLocation location;
    std::int32_t label = -1;         // N number, -1 when none
    std::int32_t programNumber = -1; // the O number on an O line
    bool blockDelete = false;        // leading '/'
    bool programEnd = false;         // holds M30 or M02 (ends the main program's scope)
    bool suspect = false;            // has a lint finding: Program::suspectMessage says which
    Control control = Control::None;
    ExprId condition = kNoExpr;      // IF / WHILE (none for a bare DOm: it loops until a GOTO)
    ExprId target = kNoExpr;         // GOTO label expression
    std::int32_t loopId = 0;         // m of DOm / ENDm
    std::int32_t partner = -1;       // WHILE <-> END block index, -1 when unmatched
    std::uint32_t controlColumn = 0; // where the control keyword starts
    std::uint32_t statement = 0;     // DPRNT, BPRNT, Modbus: its items in BlockStorage::statements
    std::span<const Assignment> assignments; // these three are stored in the program's arenas
    std::span<const Word> words;
    std::string_view comment; // text of the first comment on the line
};

// How messages name the line that opens a loop: `WHILE ... DO2`, or `DO2` for the endless form.
inline std::string loopOpening(const Block& block) {
    return (block.condition == kNoExpr ? "DO" : "WHILE ... DO") + std::to_string(block.loopId);
}

} // namespace m350::gcode
