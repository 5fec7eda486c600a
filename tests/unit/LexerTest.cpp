// The lexer on its own: token kinds, values and positions (1-based character columns, byte offsets)
// for the M350 and FANUC lexical rules.

#include "core/gcode/Lexer.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Token.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

using namespace m350::gcode;

namespace {

// A token with the texts the lexer derives on demand: what a comment says, what is wrong with an
// invalid token, or how a valid one was written; `problem` for a valid token the dialect refuses.
struct LexedToken : Token {
    std::string text;
    std::string problem;
};

std::vector<LexedToken> lex(const Dialect& dialect, std::string_view line) {
    Lexer lexer(dialect);
    std::vector<LexedToken> out;
    for (const Token& t : lexer.tokenize(line)) {
        LexedToken lexed{t, {}, {}};
        if (t.kind == TokenKind::Invalid) {
            lexed.text = lexer.issueMessage(t, line);
        } else if (t.kind == TokenKind::Comment) {
            lexed.text = std::string(commentText(t, line));
        } else {
            lexed.text = std::string(tokenSource(t, line));
            lexed.problem = lexer.issueMessage(t, line);
        }
        out.push_back(std::move(lexed));
    }
    return out;
}

std::vector<LexedToken> lexM350(std::string_view line) {
    return lex(Dialect::m350(), line);
}

std::vector<LexedToken> lexFanuc(std::string_view line) {
    return lex(Dialect::fanuc(), line);
}

// One letter per token, so a whole line's shape reads at a glance:
// L letter, 9 number, K keyword, # hash, [ ] + - * / , = as written, C compare, ( comment,
// % percent, ! invalid, $ end.
std::string shape(const std::vector<LexedToken>& tokens) {
    std::string out;
    for (const Token& t : tokens) {
        switch (t.kind) {
        case TokenKind::Number:
            out += '9';
            break;
        case TokenKind::Letter:
            out += 'L';
            break;
        case TokenKind::Keyword:
            out += 'K';
            break;
        case TokenKind::Hash:
            out += '#';
            break;
        case TokenKind::LBracket:
            out += '[';
            break;
        case TokenKind::RBracket:
            out += ']';
            break;
        case TokenKind::Plus:
            out += '+';
            break;
        case TokenKind::Minus:
            out += '-';
            break;
        case TokenKind::Star:
            out += '*';
            break;
        case TokenKind::Slash:
            out += '/';
            break;
        case TokenKind::Comma:
            out += ',';
            break;
        case TokenKind::Assign:
            out += '=';
            break;
        case TokenKind::Compare:
            out += 'C';
            break;
        case TokenKind::Comment:
            out += '(';
            break;
        case TokenKind::Percent:
            out += '%';
            break;
        case TokenKind::Invalid:
            out += '!';
            break;
        case TokenKind::End:
            out += '$';
            break;
        }
    }
    return out;
}

std::vector<std::uint32_t> columns(const std::vector<LexedToken>& tokens) {
    std::vector<std::uint32_t> out;
    for (const Token& t : tokens) {
        out.push_back(t.column);
    }
    return out;
}

} // namespace

TEST(Lexer, EmptyLineIsOnlyEnd) {
    auto tokens = lexM350("");
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].kind, TokenKind::End);
    EXPECT_EQ(tokens[0].column, 1u);
    EXPECT_EQ(shape(lexM350("   \t  ")), "$");
}

TEST(Lexer, PackedWordsSplitIntoLettersAndNumbers) {
    auto tokens = lexM350("G91G31X-#2Y#3");
    EXPECT_EQ(shape(tokens), "L9L9L-#9L#9$");
    EXPECT_EQ(columns(tokens), (std::vector<std::uint32_t>{1, 2, 4, 5, 7, 8, 9, 10, 11, 12, 13, 14}));
    EXPECT_EQ(tokens[0].letter, 'G');
    EXPECT_DOUBLE_EQ(tokens[1].number, 91.0);
    EXPECT_EQ(tokens[2].letter, 'G');
    EXPECT_DOUBLE_EQ(tokens[3].number, 31.0);
    EXPECT_EQ(tokens[4].letter, 'X');
    EXPECT_DOUBLE_EQ(tokens[7].number, 2.0);
    EXPECT_EQ(tokens[8].letter, 'Y');
    EXPECT_DOUBLE_EQ(tokens[10].number, 3.0);
    EXPECT_EQ(tokens[11].offset, 13u);
}

TEST(Lexer, LettersAreUpperCasedAndKeywordsKeepTheirSpelling) {
    auto tokens = lexM350("g1 x10 goto5");
    ASSERT_EQ(shape(tokens), "L9L9K9$");
    EXPECT_EQ(tokens[0].letter, 'G');
    EXPECT_EQ(tokens[2].letter, 'X');
    EXPECT_EQ(tokens[4].keyword, Keyword::Goto);
    EXPECT_EQ(tokens[4].text, "goto");
    EXPECT_EQ(tokens[4].column, 8u);
    // Addresses may be lower case on the M350, keywords may not; FANUC takes both.
    EXPECT_TRUE(tokens[0].problem.empty());
    EXPECT_EQ(tokens[4].problem, "keywords are upper case in the m350 dialect: write GOTO, not goto");
    EXPECT_TRUE(lexM350("GOTO5")[0].problem.empty());
    auto fanuc = lexFanuc("goto5 While");
    ASSERT_EQ(shape(fanuc), "K9K$");
    EXPECT_TRUE(fanuc[0].problem.empty());
    EXPECT_EQ(fanuc[2].keyword, Keyword::While);
    EXPECT_EQ(fanuc[2].text, "While");
    EXPECT_TRUE(fanuc[2].problem.empty());
}

TEST(Lexer, LabelThenWhileWithoutSpaces) {
    auto tokens = lexM350("N1WHILE#13>0DO13");
    ASSERT_EQ(shape(tokens), "L9K#9C9K9$");
    EXPECT_EQ(tokens[0].letter, 'N');
    EXPECT_EQ(tokens[2].keyword, Keyword::While);
    EXPECT_EQ(tokens[2].column, 3u);
    EXPECT_EQ(tokens[5].compare, BinaryOp::Gt);
    EXPECT_EQ(tokens[7].keyword, Keyword::Do);
    EXPECT_EQ(tokens[7].column, 13u);
    EXPECT_DOUBLE_EQ(tokens[8].number, 13.0);
}

TEST(Lexer, EveryKeywordIsRecognised) {
    for (int k = 0; k <= static_cast<int>(Keyword::Bcd); ++k) {
        auto keyword = static_cast<Keyword>(k);
        std::string spelling = keywordSpelling(keyword);
        SCOPED_TRACE(spelling);
        auto tokens = lexM350(spelling);
        ASSERT_EQ(shape(tokens), "K$");
        EXPECT_EQ(tokens[0].keyword, keyword);
        EXPECT_EQ(tokens[0].length, spelling.size());
    }
    EXPECT_TRUE(isFunctionKeyword(Keyword::Abs));
    EXPECT_TRUE(isFunctionKeyword(Keyword::Bcd));
    EXPECT_FALSE(isFunctionKeyword(Keyword::Mod));
    EXPECT_FALSE(isFunctionKeyword(Keyword::Goto));
    EXPECT_EQ(functionOf(Keyword::Atan), Function::Atan);
    EXPECT_EQ(functionOf(Keyword::Fup), Function::Fup);
    EXPECT_EQ(functionOf(Keyword::Bcd), Function::Bcd);
}

TEST(Lexer, ComparisonOperators) {
    auto tokens = lexM350("== != < > <= >= =");
    ASSERT_EQ(shape(tokens), "CCCCCC=$");
    const BinaryOp expected[] = {BinaryOp::Eq, BinaryOp::Ne, BinaryOp::Lt,
                                 BinaryOp::Gt, BinaryOp::Le, BinaryOp::Ge};
    const char* text[] = {"==", "!=", "<", ">", "<=", ">="};
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(tokens[i].compare, expected[i]) << text[i];
        EXPECT_EQ(tokens[i].text, text[i]);
    }
    EXPECT_EQ(columns(tokens), (std::vector<std::uint32_t>{1, 4, 7, 9, 11, 14, 17, 18}));
    // Packed: `#1!=0` and `#1>=#2` without spaces
    EXPECT_EQ(shape(lexM350("#1!=0")), "#9C9$");
    EXPECT_EQ(shape(lexM350("#1>=#2")), "#9C#9$");
}

TEST(Lexer, WordComparisonsAreKeywords) {
    auto tokens = lexM350("EQ NE LT GT LE GE");
    ASSERT_EQ(shape(tokens), "KKKKKK$");
    EXPECT_EQ(tokens[0].keyword, Keyword::Eq);
    EXPECT_EQ(tokens[5].keyword, Keyword::Ge);
}

TEST(Lexer, Numbers) {
    auto tokens = lexM350("1. .5 2.25 007 1000");
    ASSERT_EQ(shape(tokens), "99999$");
    EXPECT_DOUBLE_EQ(tokens[0].number, 1.0);
    EXPECT_DOUBLE_EQ(tokens[1].number, 0.5);
    EXPECT_DOUBLE_EQ(tokens[2].number, 2.25);
    EXPECT_DOUBLE_EQ(tokens[3].number, 7.0);
    EXPECT_DOUBLE_EQ(tokens[4].number, 1000.0);
    EXPECT_EQ(tokens[2].length, 4u);
}

TEST(Lexer, MalformedNumberIsInvalid) {
    auto tokens = lexM350("X1.2.3");
    ASSERT_EQ(shape(tokens), "L!$");
    EXPECT_EQ(tokens[1].text, "malformed number '1.2.3'");
    EXPECT_EQ(tokens[1].column, 2u);
}

TEST(Lexer, BracketsOperatorsAndPunctuation) {
    auto tokens = lexM350("#[1045+#1*3]-4/2,%");
    EXPECT_EQ(shape(tokens), "#[9+#9*9]-9/9,%$");
}

TEST(Lexer, ParenthesisCommentKeepsItsText) {
    auto tokens = lexM350("G1 (hello world) X2");
    ASSERT_EQ(shape(tokens), "L9(L9$");
    EXPECT_EQ(tokens[2].text, "hello world");
    EXPECT_EQ(tokens[2].column, 4u);
    EXPECT_EQ(tokens[2].length, 13u);
    EXPECT_EQ(tokens[3].column, 18u);
}

TEST(Lexer, MessageTextWithBracketsIsOneComment) {
    auto tokens = lexM350("#1503 = 1(T[%.0f])");
    ASSERT_EQ(shape(tokens), "#9=9($");
    EXPECT_EQ(tokens[4].text, "T[%.0f]");
    EXPECT_EQ(tokens[4].column, 10u);
}

TEST(Lexer, UnclosedCommentIsInvalid) {
    auto tokens = lexM350("G1 (abc");
    ASSERT_EQ(shape(tokens), "L9!$");
    EXPECT_EQ(tokens[2].text, "comment '(' is not closed with ')'");
    EXPECT_EQ(tokens[2].column, 4u);
}

TEST(Lexer, SemicolonAndSlashSlashEndTheLineOnM350) {
    EXPECT_EQ(shape(lexM350("G1 X1 ; M30 (x")), "L9L9$");
    EXPECT_EQ(shape(lexM350("G1 X1 // M30 (x")), "L9L9$");
    EXPECT_EQ(shape(lexM350("G1 X1//M30")), "L9L9$");
    EXPECT_EQ(shape(lexM350("// only a comment")), "$");
    // A single '/' is still a token (division, block delete)
    EXPECT_EQ(shape(lexM350("/G1 X4/2")), "/L9L9/9$");
}

TEST(Lexer, SlashSlashIsNoCommentOnFanuc) {
    EXPECT_EQ(shape(lexFanuc("G1 X1 // M30")), "L9L9//L9$");
    EXPECT_EQ(shape(lexFanuc("G1 X1 ; M30")), "L9L9$");
}

TEST(Lexer, ColumnsCountCharactersNotBytes) {
    auto tokens = lexM350("(换刀程序)G1 X5");
    ASSERT_EQ(shape(tokens), "(L9L9$");
    EXPECT_EQ(tokens[0].text, "换刀程序");
    EXPECT_EQ(tokens[1].column, 7u);
    EXPECT_EQ(tokens[1].offset, 14u); // '(' + 4 x 3 bytes + ')'
    EXPECT_EQ(tokens[3].column, 10u);
    EXPECT_EQ(tokens[3].offset, 17u);
    EXPECT_EQ(tokens[5].column, 12u);
}

TEST(Lexer, FullWidthPunctuationGetsAHint) {
    auto tokens = lexM350("G1（X）");
    ASSERT_GE(tokens.size(), 3u);
    EXPECT_EQ(tokens[2].kind, TokenKind::Invalid);
    EXPECT_EQ(tokens[2].column, 3u);
    EXPECT_EQ(tokens[2].offset, 2u);
    EXPECT_EQ(tokens[2].length, 3u);
    EXPECT_EQ(tokens[2].text, "full-width '（' is not G-code (did you mean '('?)");

    auto hash = lexM350("＃1＝5");
    ASSERT_EQ(shape(hash), "!9!9$");
    EXPECT_NE(hash[0].text.find("did you mean '#'?"), std::string::npos) << hash[0].text;
    EXPECT_NE(hash[2].text.find("did you mean '='?"), std::string::npos) << hash[2].text;
    EXPECT_EQ(hash[2].column, 3u);
}

TEST(Lexer, UnexpectedCharacters) {
    auto tokens = lexM350("G1 !X @");
    ASSERT_EQ(shape(tokens), "L9!L!$");
    EXPECT_EQ(tokens[2].text, "unexpected character '!'");
    EXPECT_EQ(tokens[4].text, "unexpected character '@'");
    EXPECT_EQ(tokens[4].column, 7u);
    auto chinese = lexM350("X1 刀");
    ASSERT_EQ(shape(chinese), "L9!$");
    EXPECT_EQ(chinese[2].text, "unexpected character '刀'");
    EXPECT_EQ(chinese[3].column, 5u);
}

TEST(Lexer, UnknownWord) {
    auto tokens = lexM350("G1 FOO X1");
    ASSERT_EQ(shape(tokens), "L9!L9$");
    EXPECT_EQ(tokens[2].text, "unknown word 'FOO'");
    EXPECT_EQ(tokens[2].column, 4u);
    EXPECT_EQ(tokens[2].length, 3u);
}

TEST(Lexer, M350SpacesSeparateWords) {
    auto tokens = lexM350("GO TO 290");
    ASSERT_EQ(shape(tokens), "!!9$");
    EXPECT_EQ(tokens[0].text, "unknown word 'GO'");
    EXPECT_EQ(tokens[1].text, "unknown word 'TO'");
}

TEST(Lexer, FanucSpacesInsideKeywordsAreIgnored) {
    auto tokens = lexFanuc("GO TO 290");
    ASSERT_EQ(shape(tokens), "K9$");
    EXPECT_EQ(tokens[0].keyword, Keyword::Goto);
    EXPECT_EQ(tokens[0].text, "GO TO");
    EXPECT_EQ(tokens[0].column, 1u);
    EXPECT_DOUBLE_EQ(tokens[1].number, 290.0);
    EXPECT_EQ(tokens[1].column, 7u);

    auto spread = lexFanuc("W H I L E [#1 L T 3] D O 1");
    ASSERT_EQ(shape(spread), "K[#9K9]K9$");
    EXPECT_EQ(spread[0].keyword, Keyword::While);
    EXPECT_EQ(spread[4].keyword, Keyword::Lt);
    EXPECT_EQ(spread[7].keyword, Keyword::Do);
}

TEST(Lexer, FanucAddressesStillSplitAtDigits) {
    auto tokens = lexFanuc("N10 G01 X 10 Y-2.5");
    ASSERT_EQ(shape(tokens), "L9L9L9L-9$");
    EXPECT_EQ(tokens[0].letter, 'N');
    EXPECT_EQ(tokens[4].letter, 'X');
    EXPECT_DOUBLE_EQ(tokens[5].number, 10.0);
    EXPECT_EQ(tokens[5].column, 11u);
}

TEST(Lexer, FanucIfGotoLine) {
    auto tokens = lexFanuc("N10 IF[#1000EQ1]GO TO 290 (comment)");
    ASSERT_EQ(shape(tokens), "L9K[#9K9]K9($");
    EXPECT_EQ(tokens[2].keyword, Keyword::If);
    EXPECT_DOUBLE_EQ(tokens[5].number, 1000.0);
    EXPECT_EQ(tokens[6].keyword, Keyword::Eq);
    EXPECT_EQ(tokens[6].column, 13u);
    EXPECT_EQ(tokens[9].keyword, Keyword::Goto);
    EXPECT_EQ(tokens[9].column, 17u);
    EXPECT_EQ(tokens[11].text, "comment");
}

TEST(Lexer, CarriageReturnIsWhitespace) {
    auto tokens = lexM350("G1 X1\r");
    EXPECT_EQ(shape(tokens), "L9L9$");
}
