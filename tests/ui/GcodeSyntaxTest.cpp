// The editor's colouring follows the parser's lexical rules: where a `/* */` comment starts and
// ends (m350 only, not inside ( ) or after // and ;) and packed keywords such as `LEABS`.
#include "ui/program/GcodeSyntax.h"

#include "core/gcode/Dialect.h"

#include <QString>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using m350::gcode::Dialect;
using m350::ui::GcodeSyntax;
using Kind = GcodeSyntax::Kind;

// The line with each span's kind as one letter under its characters: "IF" -> "KK".
std::string kinds(const GcodeSyntax& syntax, const QString& line, bool inComment = false) {
    std::vector<GcodeSyntax::Span> spans;
    syntax.scan(line, inComment, spans);
    std::string out(static_cast<std::size_t>(line.size()), ' ');
    for (const GcodeSyntax::Span& s : spans) {
        const char letter = "WANVKFLCM"[static_cast<int>(s.kind)];
        for (int i = s.start; i < s.start + s.length; ++i) {
            out[static_cast<std::size_t>(i)] = letter;
        }
    }
    return out;
}

} // namespace

TEST(GcodeSyntax, BlockCommentsEndWhereTheParserEndsThem) {
    GcodeSyntax m350(Dialect::m350());
    EXPECT_EQ(kinds(m350, QStringLiteral("X1 /* a */ Y2")), "AN CCCCCCC AN");
    EXPECT_EQ(kinds(m350, QStringLiteral("(a /* b) X1")), "CCCCCCCC AN");
    EXPECT_EQ(kinds(m350, QStringLiteral("X1 // /* c")), "AN CCCCCCC");
    EXPECT_EQ(kinds(m350, QStringLiteral("a */ X1"), true), "CCCC AN");
    EXPECT_TRUE(m350.blockCommentAfter(QStringLiteral("G1 /* open"), false));
    EXPECT_FALSE(m350.blockCommentAfter(QStringLiteral("(/* not one)"), false));
    EXPECT_FALSE(m350.blockCommentAfter(QStringLiteral("*/ G1 /* a */"), true));
    GcodeSyntax fanuc(Dialect::fanuc());
    EXPECT_FALSE(fanuc.blockCommentAfter(QStringLiteral("G1 /* open"), false));
}

TEST(GcodeSyntax, PackedKeywordsAreColouredEachAsItIs) {
    GcodeSyntax fanuc(Dialect::fanuc());
    EXPECT_EQ(kinds(fanuc, QStringLiteral("IF[#10LEABS[#11]]")), "KK VVVKKFFF VVV  ");
    EXPECT_EQ(kinds(fanuc, QStringLiteral("#3=#1ANDFIX[#2]")), "VV VVKKKFFF VV ");
    GcodeSyntax m350(Dialect::m350());
    EXPECT_EQ(kinds(m350, QStringLiteral("IF[#10LEABS[#11]]")), "KK VVVKKFFF VVV  ");
    EXPECT_EQ(kinds(m350, QStringLiteral("IF[#10leabs[#11]]")), "KK VVVAAAAA VVV  ") << "m350 keywords are upper case";
}
