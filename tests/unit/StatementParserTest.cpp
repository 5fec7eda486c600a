// The statements for devices beside the CNC read into a block: a DPRNT's text and variables with
// their digit formats (FANUC), and a Modbus statement refused by name where the dialect has none.
#include "ParsedLine.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace m350;
using namespace m350::gcode;

// The statement the line starts with, read into `block`.
void parseStatement(test::ParsedLine& line, Block& block) {
    const Token keyword = line.tokens.next();
    line.statements.parse(block, keyword);
}

TEST(StatementParser, ReadsADprntsTextAndFormattedVariables) {
    test::ParsedLine dprnt(Dialect::fanuc(), "DPRNT[TOOL*LENGTH#100[53]]");
    Block block;
    parseStatement(dprnt, block);
    EXPECT_EQ(block.control, Control::Dprnt);
    ASSERT_LT(block.statement, dprnt.storage.statements.size());
    const auto items = dprnt.storage.statements[block.statement];
    ASSERT_EQ(items.size(), 2u);
    EXPECT_EQ(items[0].text, "TOOL LENGTH");
    const ExprNode& variable = dprnt.storage.expressions[items[1].value];
    EXPECT_EQ(variable.kind, ExprKind::Variable);
    EXPECT_DOUBLE_EQ(variable.number, 100.0);
    EXPECT_EQ(items[1].integerDigits, 5);
    EXPECT_EQ(items[1].fractionDigits, 3);
    EXPECT_TRUE(dprnt.found.empty());
}

TEST(StatementParser, RefusesAStatementTheDialectLacksByName) {
    test::ParsedLine modbus(Dialect::fanuc(), "MSETDATA[1,2,3]");
    Block block;
    EXPECT_THROW(parseStatement(modbus, block), LineFindings::Failure);
    ASSERT_EQ(modbus.found.size(), 1u);
    EXPECT_NE(modbus.found[0].message.find("MSETDATA"), std::string::npos) << modbus.found[0].message;
    EXPECT_NE(modbus.found[0].message.find("fanuc"), std::string::npos) << modbus.found[0].message;
    EXPECT_EQ(modbus.found[0].column, 1u);
}

} // namespace
