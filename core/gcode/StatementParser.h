#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/BlockStorage.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/ExpressionParser.h"
#include "core/gcode/LineFindings.h"
#include "core/gcode/LineTokens.h"

#include <cstdint>
#include <vector>

namespace m350::gcode {

// The statements that talk to devices beside the CNC: FANUC's external output (POPEN, DPRNT[...],
// BPRNT[...], PCLOS) and the M350's Modbus statements (MSETDATA[...], MGETDATA[...],
// MBYTE2DATA[...], MDATA2BYTE[...]), each refused by name where the dialect lacks it. A DPRNT's
// text is no G-code (`DPRNT[TOOL*LENGTH#100[53]]`), so it is read from the line's characters; the
// Modbus arguments are expressions.
class StatementParser {
public:
    StatementParser(const Dialect& dialect, BlockStorage& storage, LineTokens& tokens, LineFindings& findings,
                    ExpressionParser& expressions)
        : dialect_(dialect), storage_(storage), pool_(storage.expressions), tokens_(tokens), findings_(findings),
          expressions_(expressions) {}

    // The statement `keyword` starts (the tokens are past it), into `block`.
    void parse(Block& block, const Token& keyword);

private:
    void parsePrintItems(Block& block, const Token& keyword);
    void parseModbusArguments(Block& block, const Token& keyword);
    void checkModbusTransfer(const Token& keyword, bool write, const std::vector<StatementItem>& arguments);
    std::uint32_t storeStatement(const std::vector<StatementItem>& items);

    const Dialect& dialect_;
    BlockStorage& storage_;
    ExpressionPool& pool_; // storage_.expressions
    LineTokens& tokens_;
    LineFindings& findings_;
    ExpressionParser& expressions_;
};

} // namespace m350::gcode
