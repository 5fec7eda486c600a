// A line's expressions read into the pool: precedence, a sign folded into its number, an
// indirection, and the refusals that fail the line (nesting beyond any program, a stray ']' with
// the #[...] its author meant).
#include "ParsedLine.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace m350;
using namespace m350::gcode;
using test::ParsedLine;

TEST(ExpressionParser, ReadsPrecedenceSignsAndIndirection) {
    ParsedLine line(Dialect::m350(), "1+2*-3 GT #[#5]");
    const ExprId top = line.expressions.parseExpression();
    const ExprNode& compare = line.storage.expressions[top];
    ASSERT_EQ(compare.kind, ExprKind::Binary);
    EXPECT_EQ(static_cast<BinaryOp>(compare.op), BinaryOp::Gt);
    const ExprNode& sum = line.storage.expressions[compare.lhs];
    ASSERT_EQ(sum.kind, ExprKind::Binary);
    EXPECT_EQ(static_cast<BinaryOp>(sum.op), BinaryOp::Add);
    const ExprNode& product = line.storage.expressions[sum.rhs];
    EXPECT_EQ(static_cast<BinaryOp>(product.op), BinaryOp::Mul);
    EXPECT_EQ(line.storage.expressions[product.rhs].kind, ExprKind::Number);
    EXPECT_DOUBLE_EQ(line.storage.expressions[product.rhs].number, -3.0) << "the sign folded into the number";
    const ExprNode& indirect = line.storage.expressions[compare.rhs];
    ASSERT_EQ(indirect.kind, ExprKind::Variable);
    EXPECT_EQ(line.storage.expressions[indirect.lhs].kind, ExprKind::Variable);
    EXPECT_DOUBLE_EQ(line.storage.expressions[indirect.lhs].number, 5.0);
    EXPECT_TRUE(line.found.empty());
    EXPECT_EQ(line.tokens.peek().kind, TokenKind::End);
}

TEST(ExpressionParser, FailsTheLineOnNestingAndStrayBrackets) {
    ParsedLine deep(Dialect::m350(), std::string(80, '[') + "1" + std::string(80, ']'));
    EXPECT_THROW(deep.expressions.parseExpression(), LineFindings::Failure);
    ASSERT_EQ(deep.found.size(), 1u);
    EXPECT_NE(deep.found[0].message.find("64"), std::string::npos) << deep.found[0].message;

    ParsedLine stray(Dialect::m350(), "#1552+#20-1]+1");
    stray.tokens.next(); // past the '#': the author meant #[1552+#20-1]
    stray.tokens.next();
    stray.expressions.parseAdditive(); // 1552+#20-1, up to the ']'
    ASSERT_EQ(stray.tokens.peek().kind, TokenKind::RBracket);
    EXPECT_THROW(stray.expressions.parseExpression(), LineFindings::Failure);
    ASSERT_EQ(stray.found.size(), 1u);
    EXPECT_NE(stray.found[0].message.find("#[1552+#20-1]"), std::string::npos) << stray.found[0].message;
}

} // namespace
