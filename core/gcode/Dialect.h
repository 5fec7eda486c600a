#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace m350::gcode {

enum class DialectId : std::uint8_t { M350, Fanuc };

// A table of parameter-backed variables that macros index as #[base + k - 1].
struct IndexedTable {
    int base = 0;
    std::string_view what; // "pocket X (params 830-845)"
    std::string_view chinese; // the same for the panel in zh_CN
    bool operator==(const IndexedTable&) const = default;
};

// Everything that differs between the M350 firmware's macro language and FANUC Custom Macro B.
// One parser and one evaluator read this table; beside it the evaluator tests the dialect once
// (ATAN's range). What each #number is, is macro::VariableMap's; where the machines themselves
// differ (tool offsets, G92, G31, the M codes the firmware or the PMC answers) the machine side
// tests `id`.
struct Dialect {
    DialectId id = DialectId::M350;
    std::string_view name;

    // Lexical rules
    bool spacesInsignificant = false;  // FANUC: `GO TO 290` == `GOTO290`
    bool slashSlashComments = false;   // M350: `// ...`
    bool semicolonComments = false;    // M350: `; ...`
    bool blockComments = false;        // M350: `/* ... */`, also over several lines (factory slib-m.nc)
    bool dotAfterComment = false;      // M350: `#1503=-3000(text).` (published macros): the `.` is ignored
    bool cStyleComparisons = false;    // == != < > <= >=
    bool bitwiseKeywords = false;      // AND OR XOR MOD
    bool unbracketedConditions = false; // M350: `IF#1300 != 0 GOTO56`, `WHILE#13>0DO13`
    bool unbracketedAddressValues = false; // M350: `G1X#63+#44Y#64+#45` (an expression up to the next address)
    bool upperCaseKeywords = false;    // M350: `while` is not WHILE
    bool atanComma = false;            // ATAN[y,x]
    bool atanSlash = false;            // ATAN[a]/[b]
    bool extendedFunctions = false;    // ASIN ACOS LN EXP BIN BCD
    int maxLoopId = 3;                 // DO1..DOm

    // Variables and calls
    bool hasVacant = false;            // FANUC's <vacant>; M350 variables start at 0
    int localFirst = 1;                // first local variable number (#0 on the M350, #1 on FANUC)
    int localCount = 33;               // locals per level (#0-#49 => 50, #1-#33 => 33)
    bool m98OpensLocalLevel = false;   // M350: every call opens one; FANUC: only G65
    bool m99RestartsMain = false;      // FANUC: M99 in a main program returns to its start
    int maxCallDepth = 15;
    std::array<std::int8_t, 26> callArguments{};    // G65/M98 address letter -> local number, -1 none
    std::array<std::int8_t, 26> handlerArguments{}; // arguments of G-code handlers (M350: X#0 Y#1 ...)
    int tCodeProgram = -1;             // M350: `T5` runs O20000 with #1 = 5
    // M350: `M98 P501 X<axis>` homes one axis (0 X .. 4 B) with the firmware's own routine, unless
    // a library defines O501 (fndX.nc .. fndB.nc and fndzero.nc call it)
    int homingProgram = -1;
    // M350: a handler program may call the handlers of other codes. FANUC: inside a program that a
    // G or M code called (parameters 6050-6091, [codes]), G and M codes are ordinary codes.
    bool codeCallsNest = true;
    int gHandlerBase = -1;             // `Gxx` runs O(9000+xx) from the G library
    int mHandlerBase = -1;             // `Mn` runs O(10000+n) from the M library
    bool externalOutput = false;       // FANUC: POPEN, DPRNT[...], BPRNT[...], PCLOS
    bool modbusStatements = false;     // M350: MSETDATA[...], MGETDATA[...] (and MBYTE2DATA, MDATA2BYTE)
    bool lookAheadCodes = false;       // FANUC: G05.1 Q1/Q0, G08 P1/P0, G05 P10000/P0 (no geometry change)
    double dwellPScale = 0.001;        // G04 P units to seconds (both: milliseconds)
    bool dwellXSeconds = false;        // FANUC: G04 X<seconds>

    std::vector<IndexedTable> indexedTables; // for the `X[#1330+#1300-1]` lint
    // Codes besides G65 whose blocks pass arguments: the machine's macro-call codes (FANUC
    // parameters 6050-6059, 6080-6089), set on a copy the controller parses with. In their blocks,
    // as in G65's, `A1E2` is A1 and the argument E2.
    std::vector<std::pair<char, std::int32_t>> argumentCodes;

    bool operator==(const Dialect&) const = default;

    static const Dialect& m350();
    static const Dialect& fanuc();
    static const Dialect* byName(std::string_view name);

    std::optional<int> callArgument(char letter) const;
    std::optional<int> handlerArgument(char letter) const;
    // The O program that would handle `G<code>` or `M<code>` (letter 'G' or 'M'): gHandlerBase +
    // code; none when the dialect has no handlers or the code is negative or beyond O99999999
    // (`M9999999930` names no program rather than overflowing into one).
    std::optional<std::int32_t> handlerProgram(char letter, std::int32_t code) const;
};

} // namespace m350::gcode
