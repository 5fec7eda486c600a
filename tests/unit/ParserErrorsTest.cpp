// What the parser reports for broken programs: the damaged lines of the M350 manual's listing with
// their hints, flow errors, recovery per line (every error of a file is listed, in line order), and
// positions counted in characters.

#include "core/gcode/Dialect.h"
#include "ParseSupport.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace m350::gcode;

namespace {

using support::listDiagnostics;
using support::Parsed;

Parsed parse(std::string_view text, const Dialect& dialect = Dialect::m350()) {
    return support::parse(text, dialect);
}

const char* kindName(DiagnosticKind kind) {
    switch (kind) {
    case DiagnosticKind::Syntax:
        return "Syntax";
    case DiagnosticKind::Flow:
        return "Flow";
    case DiagnosticKind::Lint:
        return "Lint";
    }
    return "?";
}

// Expects exactly one diagnostic, of this kind, at this position, whose message contains `text`.
void expectOnly(const Parsed& p, DiagnosticKind kind, std::uint32_t line, std::uint32_t column,
                const std::string& text) {
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    const Diagnostic& d = p.diagnostics[0];
    EXPECT_STREQ(kindName(d.kind), kindName(kind)) << d.message;
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.file, "test.nc");
    EXPECT_EQ(d.line, line) << d.message;
    EXPECT_EQ(d.column, column) << d.message;
    EXPECT_NE(d.message.find(text), std::string::npos) << "message: " << d.message << "\nexpected: " << text;
}

} // namespace

// --- the damaged lines of the manual's tool-change listing ---

TEST(ParserErrors, WhileWithLostHashBracket) {
    Parsed p = parse("N2 G04 P10\nWHILE [#1520+#13-1] NE 0] DO1\nG04 P10\nEND1");
    expectOnly(p, DiagnosticKind::Syntax, 2, 25,
               "unbalanced ']' in WHILE condition (did you mean #[1520+#13-1]?)");
}

TEST(ParserErrors, BrokenWhileDoesNotCascadeIntoUnpairedEnd) {
    // Each broken WHILE still opens its loop: no "END1 without WHILE" for the line after it.
    Parsed p = parse("WHILE [#1520+#13-1] NE 0] DO1\n"
                     "G04 P10\n"
                     "END1\n"
                     "N7 WHILE [#[1520+#11-1] NE 1]] DO2\n"
                     "END2");
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    for (const Diagnostic& d : p.diagnostics) {
        EXPECT_EQ(d.kind, DiagnosticKind::Syntax) << formatDiagnostic(d);
    }
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[1].line, 4u);
    EXPECT_EQ(p.diagnostics[1].column, 30u);
    ASSERT_EQ(p.program.blocks.size(), 5u);
    EXPECT_EQ(p.program.blocks[0].control, Control::While);
    EXPECT_EQ(p.program.blocks[0].partner, 2);
    EXPECT_EQ(p.program.blocks[3].label, 7);
    EXPECT_EQ(p.program.blocks[3].partner, 4);
}

TEST(ParserErrors, WhileWithoutLoopNumberDoesNotCascade) {
    // The loop number is lost or misspelt, so the line cannot say which END closes it; the END
    // after it must still not be reported a second time as "END1 without WHILE".
    struct Case {
        const char* line;
        std::uint32_t column;
        const char* message;
    } cases[] = {
        {"WHILE [#1 GT 0] DO", 19, "DO must be followed by a loop number 1-16, found the end of the line"},
        {"WHILE [#1 GT 0] D01", 17, "WHILE condition must be followed by DOm, found 'D'"},
        {"WHILE [#1 GT 0]", 16, "WHILE condition must be followed by DOm, found the end of the line"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.line);
        Parsed p = parse(std::string(c.line) + "\n#1 = #1 - 1\nEND1");
        expectOnly(p, DiagnosticKind::Syntax, 1, c.column, c.message);
    }
}

TEST(ParserErrors, AssignmentWithLostHashBracket) {
    Parsed p = parse("#1552+#20-1] = 1");
    expectOnly(p, DiagnosticKind::Syntax, 1, 12,
               "unbalanced ']' in the variable being assigned (did you mean #[1552+#20-1]?)");
}

TEST(ParserErrors, TableAddedInsteadOfIndexedIsALint) {
    Parsed p = parse("G53 X[#1330+#1300-1] F#1311");
    expectOnly(p, DiagnosticKind::Lint, 1, 5, "did you mean X#[1330+#1300-1]?");
    EXPECT_EQ(p.diagnostics[0].message,
              "X[#1330+#1300-1] adds the value of #1330 instead of indexing the tool pocket X table "
              "(params 830-845) (did you mean X#[1330+#1300-1]?)");
    EXPECT_FALSE(hasBlockingError(p.diagnostics));
    // The block itself is kept: a lint does not stop the program from running up to it.
    ASSERT_EQ(p.program.blocks.size(), 1u);
    EXPECT_EQ(p.program.blocks[0].words.size(), 3u);
}

TEST(ParserErrors, TableLintCoversEveryTableButNotOtherVariables) {
    Parsed y = parse("G53 Y[#1350+#1-1]");
    expectOnly(y, DiagnosticKind::Lint, 1, 5, "did you mean Y#[1350+#1-1]?");
    EXPECT_TRUE(parse("G53 Z[#1306+40] F#1312").diagnostics.empty());
    EXPECT_TRUE(parse("G53 X#[1330+#1300-1]").diagnostics.empty());
}

TEST(ParserErrors, GotoWithoutItsLabel) {
    Parsed p = parse("G04 P10\nGOTO4\nN5 M99");
    expectOnly(p, DiagnosticKind::Flow, 2, 5, "GOTO4: there is no N4");
    EXPECT_FALSE(hasBlockingError(p.diagnostics));
    Parsed conditional = parse("IF #1300 != 0 GOTO56");
    expectOnly(conditional, DiagnosticKind::Flow, 1, 19, "GOTO56: there is no N56");
}

TEST(ParserErrors, LabelsDoNotCrossProgramUnits) {
    Parsed p = parse("GOTO1\nM30\nO100\nN1 M99");
    expectOnly(p, DiagnosticKind::Flow, 1, 5, "GOTO1: there is no N1 in this program");
    Parsed o = parse("N1 M30\nO100\nGOTO1\nM99");
    expectOnly(o, DiagnosticKind::Flow, 3, 5, "GOTO1: there is no N1 in O100");
}

// The manual's listing with its damaged lines repaired, as the default machine ships it: no finding.
TEST(ParserErrors, TheRepairedToolChangeLibraryParsesCleanly) {
    std::ifstream in(std::string(M350_TEST_DATA_DIR) + "/../resources/machines/m350-linear16/slib-g.nc",
                     std::ios::binary);
    ASSERT_TRUE(in) << "slib-g.nc not found";
    std::stringstream text;
    text << in.rdbuf();
    Parser parser(Dialect::m350());
    Program program;
    parser.addFile(program, "slib-g.nc", text.str(), FileRole::GLibrary);
    parser.finish(program);
    EXPECT_TRUE(parser.diagnostics().empty()) << listDiagnostics(parser.diagnostics());
    auto unit = program.findUnit(20000);
    ASSERT_TRUE(unit.has_value());
    EXPECT_EQ(program.findHandler(20000, FileRole::GLibrary), unit);
    for (std::uint32_t b = program.units[*unit].begin; b < program.units[*unit].end; ++b) {
        const Block& block = program.blocks[b];
        if (block.control == Control::While || block.control == Control::End) {
            EXPECT_GE(block.partner, 0) << "line " << block.location.line;
        }
    }
    EXPECT_EQ(program.units[*unit].labels.count(4), 1u);
    EXPECT_EQ(program.units[*unit].labels.count(50), 1u);
}

// --- loop structure ---

TEST(ParserErrors, EndWithoutWhile) {
    Parsed p = parse("G1 X1\nEND1");
    expectOnly(p, DiagnosticKind::Flow, 2, 1, "END1 without WHILE ... DO1");
}

TEST(ParserErrors, WhileWithoutEnd) {
    Parsed p = parse("N1 WHILE [#1 LT 3] DO2\n#1 = #1 + 1");
    expectOnly(p, DiagnosticKind::Flow, 1, 4, "WHILE ... DO2 has no END2");
}

TEST(ParserErrors, EndClosingTheWrongLoop) {
    Parsed p = parse("WHILE [#1 LT 3] DO1\n#1 = #1 + 1\nEND2");
    // The DO1 also stays open (reported at line 1); the END2 is reported where it stands.
    const Diagnostic* end = nullptr;
    for (const Diagnostic& d : p.diagnostics) {
        if (d.line == 3) {
            end = &d;
        }
    }
    ASSERT_NE(end, nullptr) << listDiagnostics(p.diagnostics);
    const Diagnostic& d = *end;
    EXPECT_EQ(d.kind, DiagnosticKind::Flow);
    EXPECT_EQ(d.column, 1u);
    EXPECT_EQ(d.message, "END2 closes the loop WHILE ... DO1 opened at line 1 (expected END1)");
    EXPECT_EQ(p.program.blocks[2].partner, -1);
}

TEST(ParserErrors, SameLoopNumberNested) {
    Parsed p = parse("WHILE [#1 LT 3] DO1\nWHILE [#2 LT 3] DO1\nEND1\nEND1");
    ASSERT_FALSE(p.diagnostics.empty()) << "nested DO1 inside DO1 was accepted";
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Flow);
    EXPECT_EQ(p.diagnostics[0].line, 2u);
    EXPECT_NE(p.diagnostics[0].message.find("DO1 is already open (line 1)"), std::string::npos)
        << p.diagnostics[0].message;
}

TEST(ParserErrors, LoopNumberAbove16IsRejectedOnM350) {
    Parsed p = parse("WHILE [#1 LT 3] DO17\nEND17");
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    EXPECT_EQ(p.diagnostics[0].column, 19u);
    EXPECT_EQ(p.diagnostics[0].message, "DO17: loop numbers run from 1 to 16 in the m350 dialect");
    EXPECT_EQ(p.diagnostics[1].line, 2u);
    EXPECT_EQ(p.diagnostics[1].message, "END17: loop numbers run from 1 to 16 in the m350 dialect");
    EXPECT_TRUE(parse("WHILE [#1 LT 3] DO0\nEND0").diagnostics.size() >= 1u);
}

// --- one-line syntax errors ---

TEST(ParserErrors, MissingClosingBracket) {
    expectOnly(parse("#1 = [1+2"), DiagnosticKind::Syntax, 1, 10,
               "missing ']' to close the '[' at column 6, found the end of the line");
    expectOnly(parse("#1 = ABS[#2"), DiagnosticKind::Syntax, 1, 12, "missing ']' to close ABS[ at column 9");
    expectOnly(parse("IF [#1 GT 0 GOTO5\nN5"), DiagnosticKind::Syntax, 1, 13,
               "missing ']' to close the '[' at column 4, found 'GOTO'");
}

TEST(ParserErrors, UnknownWord) {
    expectOnly(parse("G1 FOO X1"), DiagnosticKind::Syntax, 1, 4, "unknown word 'FOO'");
}

TEST(ParserErrors, FullWidthParenthesis) {
    expectOnly(parse("G1 X1（换刀）"), DiagnosticKind::Syntax, 1, 6,
               "full-width '（' is not G-code (did you mean '('?)");
}

TEST(ParserErrors, UnclosedComment) {
    expectOnly(parse("G1 X1 (spindle on"), DiagnosticKind::Syntax, 1, 7,
               "comment '(' is not closed with ')'");
}

TEST(ParserErrors, AddressWithoutValue) {
    expectOnly(parse("G1 X"), DiagnosticKind::Syntax, 1, 4,
               "address X needs a value, found the end of the line");
    expectOnly(parse("G1 X Y2"), DiagnosticKind::Syntax, 1, 4, "address X needs a value, found 'Y'");
}

// The M350 reads `X10+5` up to the next address (the vendor's own libraries write `G91G01Z#2-#1502`,
// FactoryLanguageTest); FANUC needs the brackets.
TEST(ParserErrors, ArithmeticInAnAddressNeedsBracketsOnFanuc) {
    Parsed p = support::parse("G1 X10+5", Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:7: arithmetic in an address value needs brackets: X[...]");
    p = support::parse("G1 Y#1*2", Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:1:7: arithmetic in an address value needs brackets: Y[...]");
}

TEST(ParserErrors, FractionalVariableNumber) {
    expectOnly(parse("#1.5 = 1"), DiagnosticKind::Syntax, 1, 2,
               "variable numbers are whole numbers: #1.5 (did you mean #[...]?)");
}

TEST(ParserErrors, AndOrModAreNotM350Operators) {
    expectOnly(parse("IF [#1 GT 0 AND #2 GT 0] GOTO1\nN1"), DiagnosticKind::Syntax, 1, 13,
               "AND is not an m350 operator: write AND as [a]*[b]");
    expectOnly(parse("IF [#1 GT 0 OR #2 GT 0] GOTO1\nN1"), DiagnosticKind::Syntax, 1, 13,
               "OR is not an m350 operator: write OR as [a]+[b]");
    expectOnly(parse("#1 = #2 MOD 3"), DiagnosticKind::Syntax, 1, 9, "MOD is not an m350 operator");
    expectOnly(parse("#1 = #2 XOR 3"), DiagnosticKind::Syntax, 1, 9, "XOR is not an m350 operator");
}

TEST(ParserErrors, ModRejectionOnM350GivesAHint) {
    // AND and OR name what to write instead; MOD should too (e.g. #2-FIX[#2/3]*3).
    Parsed p = parse("#1 = #2 MOD 3");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_NE(p.diagnostics[0].message.find(": write "), std::string::npos) << p.diagnostics[0].message;
}

TEST(ParserErrors, LowerCaseKeywordsAreRejectedOnM350) {
    expectOnly(parse("N1 while [#1 LT 3] DO1\nEND1"), DiagnosticKind::Syntax, 1, 4,
               "keywords are upper case in the m350 dialect: write WHILE, not while");
    expectOnly(parse("#1 = Abs[#2]"), DiagnosticKind::Syntax, 1, 6, "write ABS, not Abs");
    EXPECT_TRUE(parse("n1 g1 x#1\nn2 #1 = ABS[-1]").diagnostics.empty());
}

TEST(ParserErrors, AtanSlashIsNotM350) {
    // not ATAN[#2] divided by #3, which the line would silently mean if the one-argument ATAN took it
    expectOnly(parse("#1 = ATAN[#2]/[#3]"), DiagnosticKind::Syntax, 1, 14,
               "ATAN[a]/[b] is not m350 syntax: write ATAN[a,b]");
}

TEST(ParserErrors, EqualsEqualsIsRejectedOnFanuc) {
    Parsed p = parse("IF [#1 == 1] GOTO5\nN5", Dialect::fanuc());
    expectOnly(p, DiagnosticKind::Syntax, 1, 8, "write EQ");
}

TEST(ParserErrors, ThenAndIfNeedTheirParts) {
    expectOnly(parse("IF [#1 EQ 1] THEN G1"), DiagnosticKind::Syntax, 1, 19,
               "THEN must be followed by an assignment such as #1 = 0, found 'G'");
    expectOnly(parse("IF [#1 EQ 1] X5"), DiagnosticKind::Syntax, 1, 14,
               "IF condition must be followed by GOTOn or THEN, found 'X'");
    expectOnly(parse("#1 ="), DiagnosticKind::Syntax, 1, 5,
               "expected a value after '=', found the end of the line");
    expectOnly(parse("DO1"), DiagnosticKind::Flow, 1, 1, "DO1 has no END1"); // a bare DO is an endless loop
    expectOnly(parse("G1 GOTO5\nN5"), DiagnosticKind::Syntax, 1, 4,
               "GOTO must start the block (after the N number)");
}

// --- recovery, order and positions ---

TEST(ParserErrors, EveryErrorOfAFileIsReportedInLineOrder) {
    Parsed p = parse("GOTO9\n"                // 1: flow, found only when the unit closes
                     "G1 X\n"                 // 2
                     "G1 X1\n"                // 3: fine
                     "#1 = [1+2\n"            // 4
                     "G53 X[#1330+#1300-1]\n" // 5: lint
                     "G1 FOO\n"               // 6
                     "END3\n"                 // 7: flow
                     "#1.5 = 1\n");           // 8
    ASSERT_EQ(p.diagnostics.size(), 7u) << listDiagnostics(p.diagnostics);
    std::vector<std::uint32_t> lines;
    for (const Diagnostic& d : p.diagnostics) {
        lines.push_back(d.line);
    }
    EXPECT_EQ(lines, (std::vector<std::uint32_t>{1, 2, 4, 5, 6, 7, 8}));
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Flow);
    EXPECT_EQ(p.diagnostics[3].kind, DiagnosticKind::Lint);
    EXPECT_EQ(p.diagnostics[5].kind, DiagnosticKind::Flow);
    EXPECT_TRUE(hasBlockingError(p.diagnostics));
    // Lines with syntax errors produce no block; the others are all there.
    ASSERT_EQ(p.program.blocks.size(), 4u);
    EXPECT_EQ(p.program.blocks[1].location.line, 3u);
}

TEST(ParserErrors, OnlyTheFirstErrorOfALineIsReported) {
    Parsed p = parse("G1 X10+5 Y FOO");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].column, 12u); // the Invalid token is found before parsing starts
}

TEST(ParserErrors, ColumnsCountCharactersAfterChineseText) {
    Parsed p = parse("(换刀程序)G1 X\n"
                     "#1503 = 1(当前刀具号) G1 X10]\n"
                     "(等待) WHILE [#1520+#13-1] NE 0] DO1\nEND1\n"
                     "(跳转)GOTO9\n"
                     "(刀)G53 X[#1330+#1300-1]");
    ASSERT_EQ(p.diagnostics.size(), 5u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[0].column, 10u);
    EXPECT_EQ(p.diagnostics[1].line, 2u);
    EXPECT_EQ(p.diagnostics[1].column, 24u);
    EXPECT_EQ(p.diagnostics[2].line, 3u);
    EXPECT_EQ(p.diagnostics[2].column, 30u);
    EXPECT_NE(p.diagnostics[2].message.find("did you mean #[1520+#13-1]?"), std::string::npos)
        << p.diagnostics[2].message;
    EXPECT_EQ(p.diagnostics[3].kind, DiagnosticKind::Flow);
    EXPECT_EQ(p.diagnostics[3].line, 5u);
    EXPECT_EQ(p.diagnostics[3].column, 9u);
    EXPECT_EQ(p.diagnostics[4].kind, DiagnosticKind::Lint);
    EXPECT_EQ(p.diagnostics[4].line, 6u);
    EXPECT_EQ(p.diagnostics[4].column, 8u);
    EXPECT_NE(p.diagnostics[4].message.find("(did you mean X#[1330+#1300-1]?)"), std::string::npos)
        << p.diagnostics[4].message;
}

TEST(ParserErrors, DiagnosticsOfSeveralFilesFollowTheOrderTheFilesWereAdded) {
    Parser parser(Dialect::m350());
    Program program;
    parser.addFile(program, "/machine/slib-g.nc", "O9001\nG1 X\nGOTO7\nM99", FileRole::GLibrary);
    parser.addFile(program, "/jobs/part.nc", "G1 FOO\nM30", FileRole::Main);
    parser.finish(program);
    const auto& d = parser.diagnostics();
    ASSERT_EQ(d.size(), 3u) << listDiagnostics(d);
    EXPECT_EQ(formatDiagnostic(d[0]), "slib-g.nc:2:4: address X needs a value, found the end of the line");
    EXPECT_EQ(formatDiagnostic(d[1]), "slib-g.nc:3:5: GOTO7: there is no N7 in O9001");
    EXPECT_EQ(formatDiagnostic(d[2]), "part.nc:1:4: unknown word 'FOO'");
}

TEST(ParserErrors, FormatDiagnosticIsFileLineColumnMessage) {
    Parsed p = parse("\n\nG1 FOO");
    ASSERT_EQ(p.diagnostics.size(), 1u);
    EXPECT_EQ(formatDiagnostic(p.diagnostics[0]), "test.nc:3:4: unknown word 'FOO'");
    Diagnostic warning = p.diagnostics[0];
    warning.severity = Severity::Warning;
    EXPECT_EQ(formatDiagnostic(warning), "test.nc:3:4: warning: unknown word 'FOO'");
}

TEST(ParserErrors, DuplicateProgramNumberInOneFile) {
    Parsed p = parse("O100\nM99\nO100\nM99");
    expectOnly(p, DiagnosticKind::Flow, 3, 1, "O100 is defined twice in this file (first at line 1)");
}
