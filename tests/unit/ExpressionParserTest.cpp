// A line's expressions read into the pool: precedence, a sign folded into its number, an
// indirection, and the refusals that fail the line (nesting beyond any program, a stray ']' with
// the #[...] its author meant).
#include "core/gcode/ExpressionParser.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350::gcode;

struct Line {
    std::vector<Diagnostic> found;
    ExpressionPool pool;
    LineTokens tokens;
    LineFindings findings{found, "part.nc"};
    ExpressionParser parser{Dialect::m350(), pool, tokens, findings};
    BlockCommentState comment;

    explicit Line(const std::string& text) {
        findings.startLine(1);
        tokens.read(Lexer(Dialect::m350()), text, comment);
        parser.startLine();
    }
};

TEST(ExpressionParser, ReadsPrecedenceSignsAndIndirection) {
    Line line("1+2*-3 GT #[#5]");
    const ExprId top = line.parser.parseExpression();
    const ExprNode& compare = line.pool[top];
    ASSERT_EQ(compare.kind, ExprKind::Binary);
    EXPECT_EQ(static_cast<BinaryOp>(compare.op), BinaryOp::Gt);
    const ExprNode& sum = line.pool[compare.lhs];
    ASSERT_EQ(sum.kind, ExprKind::Binary);
    EXPECT_EQ(static_cast<BinaryOp>(sum.op), BinaryOp::Add);
    const ExprNode& product = line.pool[sum.rhs];
    EXPECT_EQ(static_cast<BinaryOp>(product.op), BinaryOp::Mul);
    EXPECT_EQ(line.pool[product.rhs].kind, ExprKind::Number);
    EXPECT_DOUBLE_EQ(line.pool[product.rhs].number, -3.0) << "the sign folded into the number";
    const ExprNode& indirect = line.pool[compare.rhs];
    ASSERT_EQ(indirect.kind, ExprKind::Variable);
    EXPECT_EQ(line.pool[indirect.lhs].kind, ExprKind::Variable);
    EXPECT_DOUBLE_EQ(line.pool[indirect.lhs].number, 5.0);
    EXPECT_TRUE(line.found.empty());
    EXPECT_EQ(line.tokens.peek().kind, TokenKind::End);
}

TEST(ExpressionParser, FailsTheLineOnNestingAndStrayBrackets) {
    Line deep(std::string(80, '[') + "1" + std::string(80, ']'));
    EXPECT_THROW(deep.parser.parseExpression(), LineFindings::Failure);
    ASSERT_EQ(deep.found.size(), 1u);
    EXPECT_NE(deep.found[0].message.find("64"), std::string::npos) << deep.found[0].message;

    Line stray("#1552+#20-1]+1");
    stray.tokens.next(); // past the '#': the author meant #[1552+#20-1]
    stray.tokens.next();
    stray.parser.parseAdditive(); // 1552+#20-1, up to the ']'
    ASSERT_EQ(stray.tokens.peek().kind, TokenKind::RBracket);
    EXPECT_THROW(stray.parser.parseExpression(), LineFindings::Failure);
    ASSERT_EQ(stray.found.size(), 1u);
    EXPECT_NE(stray.found[0].message.find("#[1552+#20-1]"), std::string::npos) << stray.found[0].message;
}

} // namespace
