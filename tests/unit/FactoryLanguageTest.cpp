// Issue 11, "The language": what the M350's own factory files and the vendor's libraries write and
// the m350 dialect must accept: `/* */` comments (on one line and over several), address values
// that are expressions without brackets, a stray '.' after a message, and a GOTO whose label is
// missing (a flow finding that alarms only when reached). The texts are written for these tests.

#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/gcode/Dialect.h"
#include "core/gcode/Lexer.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

using namespace m350::gcode;
using m350::test::lines;
using m350::test::runM350;
using support::listDiagnostics;
using support::Parsed;
using support::show;

namespace {

Parsed parseM350(std::string_view text) {
    return support::parse(text, Dialect::m350());
}

std::string word(const Parsed& p, std::size_t block, char letter) {
    for (const Word& w : p.program.blocks.at(block).words) {
        if (w.letter == letter) {
            return show(p.program, w);
        }
    }
    return "<no " + std::string(1, letter) + ">";
}

} // namespace

// --- /* */ comments ---------------------------------------------------------------------------

TEST(FactoryLanguage, BlockCommentOnOneLineIsSkippedWhereverItStands) {
    Parsed p = support::parseClean("/* M100 开始为功能性代码*/\n"
                                   "G1 X1 /* 注释 comment */ Y2\n"
                                   "#1=5/*inside an expression*/+1\n",
                                   Dialect::m350());
    ASSERT_EQ(p.program.blocks.size(), 2u);
    EXPECT_EQ(p.program.blocks[0].location.line, 2u);
    ASSERT_EQ(p.program.blocks[0].words.size(), 3u);
    EXPECT_EQ(p.program.blocks[0].words[2].column, 24u); // Y, columns counted in characters
    EXPECT_TRUE(p.program.blocks[0].comment.empty()) << "a /* */ comment is no message text";
    EXPECT_EQ(show(p.program, p.program.blocks[1].assignments[0].value), "(5 + 1)");
}

TEST(FactoryLanguage, BlockCommentOverSeveralLinesCommentsOutCodeAndKeepsLineNumbers) {
    Parsed p = parseM350("#1=1\n"
                         "/*\n"
                         "#1=2\n"
                         "G1 X100 (旧代码 old code) #2=[\n"
                         "*/ #2=3\n"
                         "G1 X\n");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:6:4: address X needs a value, found the end of the line");
    ASSERT_EQ(p.program.blocks.size(), 2u);
    EXPECT_EQ(p.program.blocks[1].location.line, 5u); // code after */ on the same line is code
    EXPECT_EQ(p.program.blocks[1].location.column, 4u);
}

TEST(FactoryLanguage, CodeCommentedOutDoesNotRunAndAlarmsNameTheirRealLine) {
    auto run = runM350(lines({"#1=1",
                              "/* 换刀前的旧代码",
                              "#1=2",
                              "G1 X100 F1000",
                              "*/ #2=3",
                              "#3=0",
                              "#4=1/#3"}));
    EXPECT_EQ(run.number(1), 1);
    EXPECT_EQ(run.number(2), 3);
    ASSERT_TRUE(run.report.alarm.has_value());
    EXPECT_EQ(run.report.alarm->line, 7u) << run.alarmText();
    EXPECT_EQ(run.report.work[0], 0.0);
}

TEST(FactoryLanguage, AnUnclosedBlockCommentNamesItsOpening) {
    Parsed p = parseM350("G1 X1\n"
                         "G1 X2 /* a */ /* 开始\n"
                         "G1 X3\n");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]),
              "test.nc:2:15: the comment '/*' is not closed with '*/' before the end of the file");
    EXPECT_TRUE(hasBlockingError(p.diagnostics));
}

TEST(FactoryLanguage, ACommentEndWithoutItsStartIsAnError) {
    Parsed p = parseM350("G1 X1\nM5 */ M9\n");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:2:4: '*/' closes no '/*' comment");
}

// The editor's colouring (ui/program/GcodeSyntax) follows the same rules: a `/*` inside ( ) or
// after ; or // starts nothing, and the first */ closes the comment (they do not nest).
TEST(FactoryLanguage, BlockCommentsFollowTheOtherCommentsRules) {
    Parsed p = support::parseClean("(a /* b)\n"
                                   "G1 X1 // /* no block comment\n"
                                   "G1 X2 ; /* none either\n"
                                   "/* a /* b */ G1 X3\n",
                                   Dialect::m350());
    ASSERT_EQ(p.program.blocks.size(), 3u);
    EXPECT_EQ(word(p, 2, 'X'), "3");
}

TEST(FactoryLanguage, TheLexerCarriesAnOpenCommentFromLineToLine) {
    Lexer lexer(Dialect::m350());
    BlockCommentState comment;
    std::vector<Token> tokens;
    lexer.tokenize("G1 /* 开始", tokens, comment);
    EXPECT_TRUE(comment.open);
    EXPECT_TRUE(comment.openedOnThisLine);
    EXPECT_EQ(comment.column, 4u);
    EXPECT_EQ(tokens.size(), 3u); // G 1 End
    lexer.tokenize("X1 Y2", tokens, comment);
    EXPECT_TRUE(comment.open);
    EXPECT_FALSE(comment.openedOnThisLine);
    EXPECT_EQ(tokens.size(), 1u);
    lexer.tokenize("中文 */X5", tokens, comment);
    EXPECT_FALSE(comment.open);
    ASSERT_EQ(tokens.size(), 3u);
    EXPECT_EQ(tokens[0].column, 6u);
}

TEST(FactoryLanguage, FanucHasNoBlockComments) {
    Parsed p = support::parse("G1 X1 /* a */", Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    EXPECT_EQ(p.diagnostics[0].column, 7u);
}

// --- address values without brackets ----------------------------------------------------------

TEST(FactoryLanguage, AnAddressValueRunsUpToTheNextAddressLetter) {
    Parsed p = support::parseClean("G53 Z[#[1370+#1-1]]+10 F#1319\n" // factory slib-g.nc
                                   "G1X#63+#44Y#64+#45\n"            // the vendor's DDCS libraries
                                   "G91G01Z#2-#1502\n"
                                   "G53 Z#1577+#9\n" // community macros
                                   "G1 X-#1+2 Y#1*2/4 Z10+5\n"
                                   "G1 X#1+ABS[#2]Y-FIX[#3]-1\n",
                                   Dialect::m350());
    ASSERT_EQ(p.program.blocks.size(), 6u);
    EXPECT_EQ(word(p, 0, 'Z'), "(#[((1370 + #1) - 1)] + 10)");
    EXPECT_EQ(word(p, 0, 'F'), "#1319");
    EXPECT_EQ(word(p, 1, 'X'), "(#63 + #44)");
    EXPECT_EQ(word(p, 1, 'Y'), "(#64 + #45)");
    EXPECT_EQ(word(p, 2, 'Z'), "(#2 - #1502)");
    EXPECT_EQ(word(p, 3, 'Z'), "(#1577 + #9)");
    EXPECT_EQ(word(p, 4, 'X'), "(-#1 + 2)");
    EXPECT_EQ(word(p, 4, 'Y'), "((#1 * 2) / 4)");
    EXPECT_EQ(word(p, 4, 'Z'), "(10 + 5)");
    EXPECT_EQ(word(p, 5, 'X'), "(#1 + ABS[#2])");
    EXPECT_EQ(word(p, 5, 'Y'), "(-FIX[#3] - 1)");
}

TEST(FactoryLanguage, UnbracketedAddressValuesMoveTheMachine) {
    auto run = runM350(lines({"#63=1", "#44=2", "#64=3", "#45=4", "#2=5", "#9=0.5",
                              "G90 G1X#63+#44Y#64+#45 F1000", "G91G01Z#2-#9*2", "G90", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.report.work[0], 3.0);
    EXPECT_DOUBLE_EQ(run.report.work[1], 7.0);
    EXPECT_DOUBLE_EQ(run.report.work[2], 4.0);
}

TEST(FactoryLanguage, ATableAddedWithoutBracketsIsStillALint) {
    Parsed p = parseM350("G53 X#1330+#1300-1");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Lint);
    EXPECT_NE(p.diagnostics[0].message.find("(did you mean X#[1330+#1300-1]?)"), std::string::npos)
        << p.diagnostics[0].message;
}

TEST(FactoryLanguage, AComparisonDoesNotEndAnAddressValue) {
    Parsed p = parseM350("G1 X#1 EQ 2");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:8: EQ must start the block (after the N number)");
}

// --- a stray '.' after a message --------------------------------------------------------------

TEST(FactoryLanguage, AStrayDotAfterAMessageIsANoteAndTheLineRuns) {
    const char* text = "#1503=-5000(Relay test, press any key to exit).\nM30\n";
    Parsed p = parseM350(text);
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Lint);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]),
              "test.nc:1:47: warning: the '.' after the comment is not G-code: it is ignored");
    EXPECT_FALSE(p.program.blocks[0].suspect) << "a note raises no alarm when the line runs";
    EXPECT_EQ(p.program.blocks[0].assignments[0].text, "Relay test, press any key to exit");

    auto run = runM350(text);
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 1u);
    EXPECT_EQ(run.report.messages[0], "Relay test, press any key to exit");
}

TEST(FactoryLanguage, FanucRefusesTheStrayDot) {
    Parsed p = support::parse("#100=1(text).", Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:13: unexpected character '.'");
}

// --- a GOTO whose label is missing ------------------------------------------------------------

// The factory O20000 has `GOTO33` and no N33: `check` reports it, a run alarms only if it gets there.
constexpr const char* kToolChangeWithoutN33 = "O20000(换刀)\n"
                                              "IF [#1 NE 99] GOTO34\n"
                                              "GOTO33\n"
                                              "N34 #100=#1\n"
                                              "M99\n";

TEST(FactoryLanguage, AGotoWithoutItsLabelIsAFlowFindingOfItsProgram) {
    Parsed p = parseM350(std::string("M98 P20000 X5\nM30\n") + kToolChangeWithoutN33);
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Flow);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:5:5: GOTO33: there is no N33 in O20000");
    EXPECT_FALSE(hasBlockingError(p.diagnostics));
}

TEST(FactoryLanguage, AGotoWithoutItsLabelAlarmsOnlyWhenReached) {
    auto passing = runM350(std::string("M98 P20000 X5\nM30\n") + kToolChangeWithoutN33);
    EXPECT_RUN_OK(passing);
    EXPECT_EQ(passing.number(100), 5);

    auto reaching = runM350(std::string("M98 P20000 X99\nM30\n") + kToolChangeWithoutN33);
    ASSERT_TRUE(reaching.report.alarm.has_value());
    EXPECT_EQ(reaching.report.alarm->code, m350::AlarmCode::GotoMissingLabel) << reaching.alarmText();
    EXPECT_EQ(reaching.report.alarm->line, 5u);
}
