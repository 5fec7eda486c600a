// Issue 11, "FANUC Custom Macro B as real shops write it" (the lexical part): spaces inside numbers
// and variable numbers on FANUC, a keyword operator followed by a function (also packed, in both
// dialects), and text that no block reaches after M30 or an unconditional GOTO, which FANUC runs
// past and `check` reports as a lint.

#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/gcode/Dialect.h"
#include "core/gcode/Lexer.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

using namespace m350::gcode;
using m350::test::lines;
using m350::test::runFanuc;
using m350::test::runM350;
using support::listDiagnostics;
using support::Parsed;
using support::show;

namespace {

Parsed parseFanuc(std::string_view text) {
    return support::parse(text, Dialect::fanuc());
}

} // namespace

// --- FANUC: spaces are insignificant outside comments ------------------------------------------

TEST(MacroBLanguage, SpacesInsideNumbersAndVariableNumbersAreIgnoredOnFanuc) {
    auto run = runFanuc(lines({"# 1 0 0 = 2 5", "#101 = 1 . 5", "#102 = . 2 5", "G 0 1 X 1 0 . 5 F 1 0 0 0",
                               "N 1 0 M 3 0"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 25);
    EXPECT_EQ(run.number(101), 1.5);
    EXPECT_EQ(run.number(102), 0.25);
    EXPECT_DOUBLE_EQ(run.report.work[0], 10.5);
}

TEST(MacroBLanguage, KeywordsWithSpacedNumbersStillWorkOnFanuc) {
    auto run = runFanuc(lines({"#1 = 0", "#2 = 0", "WHILE [#1 LT 3] DO 1", "#1 = #1 + 1", "END 1",
                               "IF [#1 EQ 3] GOTO 1 0", "#2 = 99", "N10 GOTO 20", "#2 = 98", "N 2 0 M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(1), 3);
    EXPECT_EQ(run.number(2), 0);
}

TEST(MacroBLanguage, ASpacedNumberIsOneTokenWithItsColumn) {
    auto tokens = Lexer(Dialect::fanuc()).tokenize("X 1 0 . 5 Y2");
    ASSERT_EQ(tokens.size(), 5u);
    EXPECT_EQ(tokens[1].kind, TokenKind::Number);
    EXPECT_EQ(tokens[1].number, 10.5);
    EXPECT_EQ(tokens[1].column, 3u);
    EXPECT_EQ(tokens[2].column, 11u); // Y
}

TEST(MacroBLanguage, AMalformedSpacedNumberIsReportedWhereItStarts) {
    Parsed p = parseFanuc("G1 X 1 . 2 . 3");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:6: malformed number '1 . 2 . 3'");
}

TEST(MacroBLanguage, M350SpacesStillSeparateNumbers) {
    Parsed p = support::parse("#1 00 = 25", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    EXPECT_EQ(p.diagnostics[0].column, 4u);
}

// --- a keyword operator followed by a function -------------------------------------------------

TEST(MacroBLanguage, AKeywordOperatorBeforeAFunctionOnFanuc) {
    auto run = runFanuc(lines({"#1 = 7", "#2 = -7.6", "#5 = 3.4", "#10 = 2", "#11 = -2",
                               "IF [#1 LT ABS[#2]] GOTO9", "#20 = 1", "N9 #3 = #1 AND FIX[#5]",
                               "#4 = #1 MOD ROUND[#5]", "#6 = 0", "WHILE [#6 LE FIX[#5]] DO1", "#6 = #6 + 1", "END1",
                               "IF[#10LEABS[#11]]GOTO12", "#21 = 1", "N12 M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_TRUE(run.vacant(20)) << "7 < |-7.6| jumps over #20";
    EXPECT_EQ(run.number(3), 3);  // 7 AND 3 (0111 & 0011)
    EXPECT_EQ(run.number(4), 1);  // 7 MOD 3
    EXPECT_EQ(run.number(6), 4);  // 0..3 <= 3
    EXPECT_TRUE(run.vacant(21)) << "2 <= |-2| jumps over #21";
}

TEST(MacroBLanguage, AKeywordOperatorBeforeAFunctionOnM350) {
    auto run = runM350(lines({"#1 = 7", "#2 = -7.6", "#10 = 2", "#11 = -2", "#20 = 0", "#21 = 0",
                              "IF [#1 LT ABS[#2]] GOTO9", "#20 = 1", "N9 #6 = 0", "WHILE [#6 LE FIX[#1/2]] DO1",
                              "#6 = #6 + 1", "END1", "IF[#10LEABS[#11]]GOTO12", "#21 = 1", "N12 M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(20), 0);
    EXPECT_EQ(run.number(6), 4);
    EXPECT_EQ(run.number(21), 0);
}

TEST(MacroBLanguage, PackedKeywordsSplitWithTheirColumns) {
    auto tokens = Lexer(Dialect::fanuc()).tokenize("IF[#10LEABS[#11]]");
    ASSERT_GE(tokens.size(), 7u);
    EXPECT_EQ(tokens[4].kind, TokenKind::Keyword);
    EXPECT_EQ(tokens[4].keyword, Keyword::Le);
    EXPECT_EQ(tokens[4].column, 7u);
    EXPECT_EQ(tokens[4].length, 2u);
    EXPECT_EQ(tokens[5].keyword, Keyword::Abs);
    EXPECT_EQ(tokens[5].column, 9u);
    auto spaced = Lexer(Dialect::fanuc()).tokenize("#3=#1 MOD ROUND[#2]");
    ASSERT_GE(spaced.size(), 8u);
    EXPECT_EQ(spaced[5].keyword, Keyword::Mod);
    EXPECT_EQ(spaced[6].keyword, Keyword::Round);
    EXPECT_EQ(spaced[6].column, 11u);
}

TEST(MacroBLanguage, AndStaysNoM350OperatorBeforeAFunction) {
    Parsed p = support::parse("#3=#1 AND FIX[#2]", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:7: AND is not an m350 operator: write AND as [a]*[b]");
}

TEST(MacroBLanguage, LettersThatAreNoKeywordsStayUnknown) {
    Parsed p = parseFanuc("IF [#1 LT ABSX[#2]] GOTO9\nN9");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:8: unknown word 'LT ABSX'");
}

// --- text that nothing reaches -----------------------------------------------------------------

TEST(MacroBLanguage, TextAfterM30IsALintAndTheProgramRuns) {
    for (const Dialect* dialect : {&Dialect::m350(), &Dialect::fanuc()}) {
        Parsed p = support::parse("G0 X1\nM30\n#\n%\n", *dialect);
        ASSERT_EQ(p.diagnostics.size(), 1u) << dialect->name << "\n" << listDiagnostics(p.diagnostics);
        EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Lint);
        EXPECT_EQ(formatDiagnostic(p.diagnostics[0]),
                  "test.nc:3:2: '#' must be followed by a variable number or [expression], found the end of the "
                  "line (never reached after the M30 on line 2, so the program still runs)");
        EXPECT_FALSE(hasBlockingError(p.diagnostics));
    }
    auto run = runFanuc("#100 = 1\nM30\n#\n");
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 1);
}

TEST(MacroBLanguage, TextAfterAnUnconditionalGotoIsALintUpToTheNextLabel) {
    Parsed p = parseFanuc("#1 = 1\nGOTO 5\n#\nX1 X\nN5 #2 = 2\nM30");
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Lint);
    EXPECT_EQ(p.diagnostics[0].line, 3u);
    EXPECT_EQ(p.diagnostics[1].kind, DiagnosticKind::Lint);
    EXPECT_EQ(p.diagnostics[1].line, 4u);
    EXPECT_NE(p.diagnostics[1].message.find("never reached after the GOTO on line 2"), std::string::npos);
    auto run = runFanuc("#1 = 1\nGOTO 5\n#\nN5 #2 = 2\nM30");
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(2), 2);
}

TEST(MacroBLanguage, ReachableBrokenLinesStaySyntaxErrors) {
    // a label may be jumped to; a conditional GOTO falls through; a loop's exit lands after END
    for (const char* text : {"GOTO 5\nN4 #\nN5 M30", "IF [#1 EQ 0] GOTO 5\n#\nN5 M30",
                             "WHILE [#1 LT 2] DO1\n#1 = #1 + 1\nGOTO 9\nEND1\n#\nN9 M30", "/M30\n#\nM30"}) {
        Parsed p = parseFanuc(text);
        ASSERT_EQ(p.diagnostics.size(), 1u) << text << "\n" << listDiagnostics(p.diagnostics);
        EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax) << text;
        EXPECT_TRUE(hasBlockingError(p.diagnostics)) << text;
    }
}

TEST(MacroBLanguage, AnOProgramAfterM99IsReachedByItsCall) {
    Parsed p = support::parse("M98 P100\nM30\nO100\n#1 = 1\nM99\n#\nO200\n#\nM99", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Lint); // line 6, after M99
    EXPECT_EQ(p.diagnostics[0].line, 6u);
    EXPECT_EQ(p.diagnostics[1].kind, DiagnosticKind::Syntax); // line 8, the first line of O200
    EXPECT_EQ(p.diagnostics[1].line, 8u);
}
