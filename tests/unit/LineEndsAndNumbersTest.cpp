// Issue 13, silently wrong results of the lexer: a lone CR merged blocks, `1E308` was read as 1 and
// an ignored E word, and labels beyond 2^31 were clamped into one another.

#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/gcode/Dialect.h"
#include "core/gcode/LineSplitter.h"
#include "core/gcode/SourceText.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

using namespace m350::gcode;
using m350::test::runFanuc;
using m350::test::runM350;
using support::listDiagnostics;
using support::Parsed;

namespace {

std::vector<std::string> split(std::string_view text) {
    std::vector<std::string> out;
    LineSplitter lines(text);
    std::string_view line;
    while (lines.next(line)) {
        out.emplace_back(line);
    }
    return out;
}

} // namespace

// --- line ends ---------------------------------------------------------------------------------

TEST(LineEnds, LfCrLfAndALoneCrEachEndOneLine) {
    EXPECT_EQ(split("a\rb\r\nc\n\rd"), (std::vector<std::string>{"a", "b", "c", "", "d"}));
    EXPECT_EQ(split("a\r\r\nb\r"), (std::vector<std::string>{"a", "", "b", ""}));
    EXPECT_EQ(split(""), (std::vector<std::string>{""}));
    EXPECT_EQ(split("\n"), (std::vector<std::string>{"", ""}));
}

TEST(LineEnds, BlocksOfACrOnlyFileDoNotMerge) {
    Parsed p = support::parseClean("G1 X1\rG1 X2\r\nG1 X3\n\rG1 X4", Dialect::m350());
    ASSERT_EQ(p.program.blocks.size(), 4u);
    const std::uint32_t expected[] = {1, 2, 3, 5};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(p.program.blocks[i].location.line, expected[i]);
        ASSERT_EQ(p.program.blocks[i].words.size(), 2u);
        EXPECT_EQ(p.program.blocks[i].words[1].number, static_cast<double>(i + 1));
    }
}

TEST(LineEnds, ErrorsAndAlarmsOfACrOnlyFileNameTheirLine) {
    Parsed p = support::parse("G1 X1\rG1 X\r", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:2:4: address X needs a value, found the end of the line");
    auto run = runM350("#1=0\r#2=5\r#3=#2/#1\rM30\r");
    ASSERT_TRUE(run.report.alarm.has_value());
    EXPECT_EQ(run.report.alarm->line, 3u) << run.alarmText();
    EXPECT_EQ(run.number(2), 5) << "the line before the alarm ran on its own";
}

TEST(LineEnds, AnEncodingErrorAfterCrLinesNamesItsLine) {
    auto decoded = decodeSource("cr.nc", std::string_view("G1 X1\rG1 X2\r(\x80\xff)", 15));
    const auto* error = std::get_if<SourceReadError>(&decoded);
    ASSERT_NE(error, nullptr);
    EXPECT_NE(error->message.find("line 3, column 2"), std::string::npos) << error->message;
}

// --- E is no exponent ---------------------------------------------------------------------------

TEST(ExponentNumbers, AreSyntaxErrorsInBothDialects) {
    struct Case {
        const char* text;
        std::uint32_t column;
        const char* written;
    };
    for (const Dialect* dialect : {&Dialect::m350(), &Dialect::fanuc()}) {
        for (Case c : {Case{"#1=1E308", 4, "1E308"}, Case{"G4 P1E3", 5, "1E3"}, Case{"G1 X1.5e-3", 5, "1.5e-3"},
                       Case{"#1=[2*1E+2]", 7, "1E+2"}, Case{"IF [#1 GT 1E3] GOTO5\nN5", 11, "1E3"}}) {
            Parsed p = support::parse(c.text, *dialect);
            ASSERT_EQ(p.diagnostics.size(), 1u) << dialect->name << ": " << c.text << "\n"
                                                << listDiagnostics(p.diagnostics);
            EXPECT_EQ(formatDiagnostic(p.diagnostics[0]),
                      "test.nc:1:" + std::to_string(c.column) + ": '" + c.written +
                          "' is not a G-code number: there is no exponent (E) notation; write the number in digits");
        }
    }
}

TEST(ExponentNumbers, AFanucMacroCallKeepsItsEArgument) {
    auto run = runFanuc("G65 P100 A1E2\nM30\nO100\n#100 = #1\n#101 = #8\nM99\n");
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 1);
    EXPECT_EQ(run.number(101), 2);
}

// A variable's number followed by E is two words: the probing package's `...X#31Y#32E2.` passes
// Y = #32 and E = 2., in both dialects; only a number written with E is refused.
TEST(ExponentNumbers, AnEAfterAVariableStartsTheNextWord) {
    for (const Dialect* dialect : {&Dialect::m350(), &Dialect::fanuc()}) {
        Parsed p = support::parse("G1X#31Y#32E2.\n#1=#2E-3\n", *dialect);
        ASSERT_TRUE(p.diagnostics.empty()) << dialect->name << ":\n" << listDiagnostics(p.diagnostics);
        const Block& move = p.program.blocks.at(0);
        ASSERT_EQ(move.words.size(), 4u) << dialect->name;
        EXPECT_EQ(move.words[2].letter, 'Y');
        EXPECT_EQ(support::show(p.program, move.words[2].value), "#32");
        EXPECT_EQ(move.words[3].letter, 'E');
        EXPECT_TRUE(move.words[3].isNumber());
        EXPECT_EQ(move.words[3].number, 2.0);
        const Block& assignment = p.program.blocks.at(1);
        ASSERT_EQ(assignment.words.size(), 1u) << dialect->name;
        EXPECT_EQ(assignment.words[0].letter, 'E');
        EXPECT_EQ(assignment.words[0].number, -3.0);
    }
}

TEST(ExponentNumbers, AProbingCallPassesEAfterAVariable) {
    auto run = runFanuc("#7=6.#15=150.#11=1.#13=0.5#19=3.#20=12.#23=4.#31=25.#32=-18.5\n"
                        "G65P9730D#7F#15H#11M#13S#19T#20W#23X#31Y#32E2.\nM30\n"
                        "O9730\n#100=#7+#9+#11+#13+#19+#20+#23\n#101=#24\n#102=#25\n#103=#8\nM99\n");
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 6 + 150 + 1 + 0.5 + 3 + 12 + 4);
    EXPECT_EQ(run.number(101), 25);
    EXPECT_EQ(run.number(102), -18.5);
    EXPECT_EQ(run.number(103), 2);
}

// --- labels stay exact --------------------------------------------------------------------------

TEST(Labels, BeyondEightDigitsAreRefused) {
    for (const Dialect* dialect : {&Dialect::m350(), &Dialect::fanuc()}) {
        Parsed n = support::parse("N99999999999 G1 X1\nN2147483647 M30", *dialect);
        ASSERT_EQ(n.diagnostics.size(), 2u) << listDiagnostics(n.diagnostics);
        EXPECT_EQ(formatDiagnostic(n.diagnostics[0]),
                  "test.nc:1:2: N99999999999: sequence numbers run from 0 to 99999999 (8 digits)");
        EXPECT_EQ(n.diagnostics[1].line, 2u);
        Parsed go = support::parse("GOTO 99999999999\nIF [1 EQ 1] GOTO100000000\nGOTO-1", *dialect);
        ASSERT_EQ(go.diagnostics.size(), 3u) << listDiagnostics(go.diagnostics);
        EXPECT_EQ(formatDiagnostic(go.diagnostics[0]),
                  "test.nc:1:6: GOTO99999999999: sequence numbers run from 0 to 99999999 (8 digits)");
        EXPECT_EQ(go.diagnostics[1].column, 17u);
        EXPECT_EQ(go.diagnostics[2].column, 5u);
    }
}

TEST(Labels, ProgramNumbersBeyondEightDigitsAreRefused) {
    Parsed p = support::parse("M98 P1\nM30\nO99999999999\nM99\nO1\nM99", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]),
              "test.nc:3:2: O99999999999: program numbers run from 0 to 99999999 (8 digits)");
}

TEST(Labels, TheLargestLabelIsExact) {
    auto run = runM350("#1=0\nGOTO 99999999\nN99999998 #1=1\nN99999999 #2=2\nM30\n");
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(1), 0);
    EXPECT_EQ(run.number(2), 2);
}

TEST(Labels, AComputedGotoOutOfRangeAlarmsWithoutRounding) {
    auto run = runM350("#1=99999999999\nGOTO#1\nN99999999 M30\n");
    ASSERT_TRUE(run.report.alarm.has_value());
    EXPECT_EQ(run.report.alarm->code, m350::AlarmCode::GotoMissingLabel);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.report.alarm->message, "GOTO99999999999: sequence numbers run from 0 to 99999999");
}
