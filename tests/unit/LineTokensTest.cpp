// The line the parser reads as tokens: peeking and taking them (never past the end), going back,
// quoting a token's text, and a byte's column counted in characters.
#include "core/gcode/LineTokens.h"

#include "core/gcode/Dialect.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350::gcode;

TEST(LineTokens, TakesPeeksAndQuotesTheLinesTokens) {
    LineTokens tokens;
    BlockCommentState comment;
    const std::string line = "(进给) N10 G1 X#1 IF";
    tokens.read(Lexer(Dialect::m350()), line, comment);
    EXPECT_TRUE(tokens.startsLabelled()) << "an N number after a comment";
    EXPECT_EQ(tokens.peek().kind, TokenKind::Comment);
    EXPECT_EQ(tokens.describe(tokens.peek()), "a comment");
    tokens.next();
    const Token& n = tokens.next();
    EXPECT_EQ(tokens.source(n), "N");
    EXPECT_EQ(n.column, 6u) << "columns count characters, not UTF-8 bytes";
    EXPECT_EQ(tokens.columnAt(n.offset), 6u);
    EXPECT_EQ(tokens.columnAt(line.size()), 19u); // after its 18 characters
    EXPECT_EQ(tokens.columnAt(0), 1u) << "asked again from the start";
    const std::size_t mark = tokens.position();
    EXPECT_EQ(tokens.source(tokens.next()), "10");
    tokens.moveTo(mark);
    EXPECT_EQ(tokens.describe(tokens.next()), "'10'");
    while (tokens.peek().kind != TokenKind::Keyword) {
        tokens.next();
    }
    EXPECT_TRUE(tokens.atKeyword(Keyword::If));
    tokens.next();
    EXPECT_EQ(tokens.peek(LineTokens::kLookahead).kind, TokenKind::End) << "peeking stays inside the list";
    const std::size_t end = tokens.position();
    EXPECT_EQ(tokens.next().kind, TokenKind::End);
    EXPECT_EQ(tokens.position(), end) << "next() stays at the first End";
    EXPECT_EQ(tokens.describe(tokens.peek()), "the end of the line");

    tokens.read(Lexer(Dialect::m350()), "/ O100", comment);
    EXPECT_TRUE(tokens.startsLabelled()) << "an O number after a block delete";
    tokens.read(Lexer(Dialect::m350()), "G0 N5", comment);
    EXPECT_FALSE(tokens.startsLabelled());
}

} // namespace
