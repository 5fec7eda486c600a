#include "core/gcode/Dialect.h"

namespace m350::gcode {

namespace {

using LetterMap = std::array<std::int8_t, 26>;

LetterMap letters(std::initializer_list<std::pair<char, int>> entries) {
    LetterMap map;
    map.fill(-1);
    for (auto [letter, variable] : entries) {
        map[static_cast<std::size_t>(letter - 'A')] = static_cast<std::int8_t>(variable);
    }
    return map;
}

Dialect makeM350() {
    Dialect d;
    d.id = DialectId::M350;
    d.name = "m350";
    d.slashSlashComments = true;
    d.semicolonComments = true;
    d.blockComments = true;
    d.dotAfterComment = true;
    d.cStyleComparisons = true;
    d.unbracketedConditions = true;
    d.unbracketedAddressValues = true; // the vendor's own libraries: `G91G01Z#2-#1502`
    d.upperCaseKeywords = true;
    d.atanComma = true;
    d.maxLoopId = 16; // the factory macros use DO1..DO16
    d.hasVacant = false;
    d.localFirst = 0;
    d.localCount = 50; // #0-#49
    d.m98OpensLocalLevel = true;
    d.maxCallDepth = 15;
    // M350 argument specification (community G/M reference, confirmed by the factory macros)
    d.callArguments = letters({{'X', 1}, {'Y', 2}, {'Z', 3}, {'A', 4}, {'B', 5}, {'C', 6}, {'I', 7}, {'J', 8},
                               {'K', 9}, {'R', 10}, {'H', 12}, {'Q', 14}, {'D', 15}, {'F', 16}, {'S', 17}});
    // G-code handlers get X#0 Y#1 Z#2 A#3 B#4 C#5 (O9053: `G91G00X#0Y#1Z#2A#3B#4C#5`); the rest as above,
    // and P#13 (our choice, for the cycles' dwell: the firmware's is not known)
    d.handlerArguments = letters({{'X', 0}, {'Y', 1}, {'Z', 2}, {'A', 3}, {'B', 4}, {'C', 5}, {'I', 7}, {'J', 8},
                                  {'K', 9}, {'R', 10}, {'H', 12}, {'P', 13}, {'Q', 14}, {'D', 15}, {'F', 16},
                                  {'S', 17}});
    d.modbusStatements = true;
    d.tCodeProgram = 20000;
    d.homingProgram = 501;
    d.gHandlerBase = 9000;
    d.mHandlerBase = 10000;
    d.indexedTables = {
        {1330, "the tool pocket X table (params 830-845)", "刀位X坐标表(参数830-845)"},
        {1350, "the tool pocket Y table (params 850-865)", "刀位Y坐标表(参数850-865)"},
        {1370, "the tool pocket Z table (params 870-885)", "刀位Z坐标表(参数870-885)"},
        {1390, "the tool X offset table (params 890-905)", "刀具X偏置表(参数890-905)"},
        {1410, "the tool Y offset table (params 910-925)", "刀具Y偏置表(参数910-925)"},
        {1430, "the tool Z offset table (params 930-945)", "刀具Z偏置表(参数930-945)"},
        {1473, "the virtual tool Z offset table (params 973-992)", "虚拟刀具Z偏置表(参数973-992)"},
        {1520, "the inputs IN01-IN24", "输入IN01-IN24"},
        {1552, "the outputs OUT01-OUT21", "输出OUT01-OUT21"},
    };
    return d;
}

Dialect makeFanuc() {
    Dialect d;
    d.id = DialectId::Fanuc;
    d.name = "fanuc";
    d.spacesInsignificant = true;
    d.bitwiseKeywords = true;
    d.atanSlash = true;
    d.atanComma = true; // later 0i series accept ATAN[a,b] as well
    d.extendedFunctions = true;
    d.maxLoopId = 3;
    d.hasVacant = true;
    d.localFirst = 1;
    d.localCount = 33; // #1-#33
    d.m98OpensLocalLevel = false;
    d.m99RestartsMain = true;
    d.maxCallDepth = 15;
    // Argument specification I
    d.callArguments = letters({{'A', 1}, {'B', 2}, {'C', 3}, {'I', 4}, {'J', 5}, {'K', 6}, {'D', 7}, {'E', 8},
                               {'F', 9}, {'H', 11}, {'M', 13}, {'Q', 17}, {'R', 18}, {'S', 19}, {'T', 20},
                               {'U', 21}, {'V', 22}, {'W', 23}, {'X', 24}, {'Y', 25}, {'Z', 26}});
    d.handlerArguments = d.callArguments;
    d.codeCallsNest = false;
    d.dwellXSeconds = true;
    d.lookAheadCodes = true;
    d.externalOutput = true;
    return d;
}

} // namespace

const Dialect& Dialect::m350() {
    static const Dialect dialect = makeM350();
    return dialect;
}

const Dialect& Dialect::fanuc() {
    static const Dialect dialect = makeFanuc();
    return dialect;
}

const Dialect* Dialect::byName(std::string_view name) {
    if (name == "m350") {
        return &m350();
    }
    if (name == "fanuc") {
        return &fanuc();
    }
    return nullptr;
}

std::optional<int> Dialect::callArgument(char letter) const {
    int v = callArguments[static_cast<std::size_t>(letter - 'A')];
    return v < 0 ? std::nullopt : std::optional<int>(v);
}

std::optional<int> Dialect::handlerArgument(char letter) const {
    int v = handlerArguments[static_cast<std::size_t>(letter - 'A')];
    return v < 0 ? std::nullopt : std::optional<int>(v);
}

std::optional<std::int32_t> Dialect::handlerProgram(char letter, std::int32_t code) const {
    constexpr std::int64_t kLargestProgram = 99999999; // O numbers have 8 digits
    const int base = letter == 'M' ? mHandlerBase : gHandlerBase;
    if (base < 0 || code < 0 || std::int64_t{base} + code > kLargestProgram) {
        return std::nullopt;
    }
    return base + code;
}

} // namespace m350::gcode
