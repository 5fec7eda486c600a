// The checks of a line beyond its grammar: an exponent fails the line, a comment inside a comment
// is noted at its '(', and a broken WHILE line still stands for its loop.
#include "ParsedLine.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;
using namespace m350::gcode;
using test::ParsedLine;

TEST(LineChecks, RefusesExponentsNotesNestedCommentsAndKeepsABrokenLoopsBlock) {
    ParsedLine exponent(Dialect::m350(), "#1=1E308");
    EXPECT_THROW(exponent.checks.checkExponents(), LineFindings::Failure);
    ASSERT_EQ(exponent.found.size(), 1u);
    EXPECT_NE(exponent.found[0].message.find("1E308"), std::string::npos) << exponent.found[0].message;
    EXPECT_EQ(exponent.found[0].column, 4u);

    ParsedLine variable(Dialect::m350(), "G1 Y#32E2.");
    EXPECT_NO_THROW(variable.checks.checkExponents()) << "a variable's number is no mantissa";

    ParsedLine nested(Dialect::m350(), "G0 X1 (rough (T1) pass)");
    nested.checks.lintNestedComments();
    ASSERT_EQ(nested.found.size(), 1u);
    EXPECT_EQ(nested.found[0].severity, Severity::Warning);
    EXPECT_EQ(nested.found[0].column, 14u) << "at the inner '('";

    ParsedLine loop(Dialect::m350(), "N5 WHILE [#1 LT ] DO2");
    const std::optional<Block> block = loop.checks.brokenLoopBlock(Block{});
    ASSERT_TRUE(block);
    EXPECT_EQ(block->control, Control::While);
    EXPECT_EQ(block->loopId, 2);
    ParsedLine plain(Dialect::m350(), "G1 X[1+]");
    EXPECT_FALSE(plain.checks.brokenLoopBlock(Block{}));
}

} // namespace
