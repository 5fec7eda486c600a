// The parser on well-formed M350 programs: the structure of blocks, words, assignments, control
// statements and expression trees, and how a file is split into O-program units.

#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace m350::gcode;

namespace {

struct Parsed {
    Program program;
    std::vector<Diagnostic> diagnostics;
};

Parsed parse(std::string_view text, const Dialect& dialect = Dialect::m350()) {
    Parsed p;
    Parser parser(dialect);
    parser.addFile(p.program, "test.nc", text, FileRole::Main);
    parser.finish(p.program);
    p.diagnostics = parser.diagnostics();
    return p;
}

std::string listDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics) {
        out += formatDiagnostic(d) + "\n";
    }
    return out;
}

// Renders an expression tree with every binary node parenthesised: `(#1 + (2 * 3))`.
std::string show(const Program& program, ExprId id) {
    if (id == kNoExpr) {
        return "<none>";
    }
    const ExprNode& n = program.expressions[id];
    switch (n.kind) {
    case ExprKind::Number: {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", n.number);
        return buffer;
    }
    case ExprKind::Variable:
        if (n.lhs == kNoExpr) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "#%g", n.number);
            return buffer;
        }
        return "#[" + show(program, n.lhs) + "]";
    case ExprKind::Unary:
        return (static_cast<UnaryOp>(n.op) == UnaryOp::Negate ? "-" : "+") + show(program, n.lhs);
    case ExprKind::Binary: {
        static const char* ops[] = {"+", "-", "*", "/", "MOD", "AND", "OR", "XOR", "==", "!=", "<", ">", "<=", ">="};
        return "(" + show(program, n.lhs) + " " + ops[n.op] + " " + show(program, n.rhs) + ")";
    }
    case ExprKind::Function: {
        static const char* names[] = {"ABS", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT",
                                      "ROUND", "FIX", "FUP", "LN", "EXP", "BIN", "BCD"};
        std::string out = std::string(names[n.op]) + "[" + show(program, n.lhs);
        if (n.rhs != kNoExpr) {
            out += "," + show(program, n.rhs);
        }
        return out + "]";
    }
    }
    return "?";
}

std::string letters(const Block& block) {
    std::string out;
    for (const Word& w : block.words) {
        out += w.letter;
    }
    return out;
}

// Parses one clean program and returns it; any diagnostic fails the test.
Parsed parseClean(std::string_view text) {
    Parsed p = parse(text);
    EXPECT_TRUE(p.diagnostics.empty()) << listDiagnostics(p.diagnostics);
    return p;
}

} // namespace

TEST(Parser, PackedWordsWithVariablesAndIndirection) {
    Parsed p = parseClean("G91G31X-#2Y#3 F#22 P#[1045+#1*3] L#28 K0 Q1");
    ASSERT_EQ(p.program.blocks.size(), 1u);
    const Block& b = p.program.blocks[0];
    ASSERT_EQ(letters(b), "GGXYFPLKQ");
    const Program& g = p.program;
    EXPECT_EQ(show(g, b.words[0].value), "91");
    EXPECT_EQ(show(g, b.words[1].value), "31");
    EXPECT_EQ(show(g, b.words[2].value), "-#2");
    EXPECT_EQ(g.expressions[b.words[2].value].kind, ExprKind::Unary);
    EXPECT_EQ(show(g, b.words[3].value), "#3");
    EXPECT_EQ(show(g, b.words[4].value), "#22");
    const ExprNode& pValue = g.expressions[b.words[5].value];
    EXPECT_EQ(pValue.kind, ExprKind::Variable);
    ASSERT_NE(pValue.lhs, kNoExpr);
    EXPECT_EQ(show(g, pValue.lhs), "(1045 + (#1 * 3))");
    EXPECT_EQ(show(g, b.words[6].value), "#28");
    EXPECT_EQ(show(g, b.words[7].value), "0");
    EXPECT_EQ(show(g, b.words[8].value), "1");
    std::vector<std::uint32_t> cols;
    for (const Word& w : b.words) {
        cols.push_back(w.column);
    }
    EXPECT_EQ(cols, (std::vector<std::uint32_t>{1, 4, 7, 11, 15, 20, 34, 39, 42}));
    EXPECT_EQ(b.control, Control::None);
    EXPECT_TRUE(b.assignments.empty());
}

TEST(Parser, NegativeNumbersFoldButNegatedVariablesStayUnary) {
    Parsed p = parseClean("X-5 Y+2.5 Z-#2 A-[#1+1]");
    const Block& b = p.program.blocks.at(0);
    ASSERT_EQ(letters(b), "XYZA");
    EXPECT_EQ(p.program.expressions[b.words[0].value].kind, ExprKind::Number);
    EXPECT_DOUBLE_EQ(p.program.expressions[b.words[0].value].number, -5.0);
    EXPECT_DOUBLE_EQ(p.program.expressions[b.words[1].value].number, 2.5);
    EXPECT_EQ(show(p.program, b.words[2].value), "-#2");
    EXPECT_EQ(show(p.program, b.words[3].value), "-(#1 + 1)");
}

TEST(Parser, StatementRightAfterItsLabel) {
    Parsed p = parseClean("N6#9=#9+#21");
    const Block& b = p.program.blocks.at(0);
    EXPECT_EQ(b.label, 6);
    ASSERT_EQ(b.assignments.size(), 1u);
    EXPECT_EQ(show(p.program, b.assignments[0].index), "#9");
    EXPECT_EQ(show(p.program, b.assignments[0].value), "(#9 + #21)");
    EXPECT_EQ(b.assignments[0].column, 3u);
    EXPECT_FALSE(b.assignments[0].hasText);
    EXPECT_TRUE(b.words.empty());
    ASSERT_EQ(p.program.units.size(), 1u);
    EXPECT_EQ(p.program.units[0].labels.at(6), (std::vector<std::uint32_t>{0}));
}

TEST(Parser, IfGotoWithUnbracketedConditions) {
    Parsed p = parseClean("IF#1300 != 0 GOTO56\n"
                          "IF #1>[#1301] GOTO4\n"
                          "IF [#1515+#1516+#1517]>=3 GOTO50\n"
                          "IF #1300==#1 GOTO4\n"
                          "IF #1!= 0 GOTO57\n"
                          "N4\nN50\nN56\nN57");
    const auto& blocks = p.program.blocks;
    ASSERT_EQ(blocks.size(), 9u);
    const char* conditions[] = {"(#1300 != 0)", "(#1 > #1301)", "(((#1515 + #1516) + #1517) >= 3)",
                                "(#1300 == #1)", "(#1 != 0)"};
    const char* targets[] = {"56", "4", "50", "4", "57"};
    for (int i = 0; i < 5; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(blocks[i].control, Control::IfGoto);
        EXPECT_EQ(show(p.program, blocks[i].condition), conditions[i]);
        EXPECT_EQ(show(p.program, blocks[i].target), targets[i]);
        EXPECT_EQ(blocks[i].controlColumn, 1u);
        EXPECT_EQ(blocks[i].location.line, static_cast<std::uint32_t>(i + 1));
    }
    EXPECT_EQ(p.program.expressions[blocks[0].target].column, 18u);
}

TEST(Parser, GotoNumberAndComputedGoto) {
    Parsed p = parseClean("N1 GOTO7\nGOTO[#1+2]\nGOTO#5\nN7");
    const auto& blocks = p.program.blocks;
    ASSERT_EQ(blocks.size(), 4u);
    EXPECT_EQ(blocks[0].label, 1);
    EXPECT_EQ(blocks[0].control, Control::Goto);
    EXPECT_EQ(blocks[0].controlColumn, 4u);
    EXPECT_EQ(show(p.program, blocks[0].target), "7");
    EXPECT_EQ(blocks[1].control, Control::Goto);
    EXPECT_EQ(show(p.program, blocks[1].target), "(#1 + 2)");
    EXPECT_EQ(show(p.program, blocks[2].target), "#5");
    EXPECT_EQ(blocks[3].label, 7);
    EXPECT_EQ(blocks[3].control, Control::None);
}

TEST(Parser, WhileDoEndWithLoopNumbersUpTo16) {
    Parsed p = parseClean("WHILE [#1 LT 10] DO16\n"
                          "#1=#1+1\n"
                          "END16\n"
                          "N1WHILE#13>0DO13\n"
                          "#13=#13-1\n"
                          "END13");
    const auto& blocks = p.program.blocks;
    ASSERT_EQ(blocks.size(), 6u);
    EXPECT_EQ(blocks[0].control, Control::While);
    EXPECT_EQ(blocks[0].loopId, 16);
    EXPECT_EQ(show(p.program, blocks[0].condition), "(#1 < 10)");
    EXPECT_EQ(blocks[0].partner, 2);
    EXPECT_EQ(blocks[2].control, Control::End);
    EXPECT_EQ(blocks[2].loopId, 16);
    EXPECT_EQ(blocks[2].partner, 0);
    EXPECT_EQ(blocks[3].label, 1);
    EXPECT_EQ(blocks[3].control, Control::While);
    EXPECT_EQ(blocks[3].controlColumn, 3u);
    EXPECT_EQ(blocks[3].loopId, 13);
    EXPECT_EQ(show(p.program, blocks[3].condition), "(#13 > 0)");
    EXPECT_EQ(blocks[3].partner, 5);
    EXPECT_EQ(blocks[5].partner, 3);
    EXPECT_EQ(blocks[1].partner, -1);
}

TEST(Parser, NestedAndSequentialLoopsPair) {
    Parsed p = parseClean("WHILE [#1 LT 3] DO1\n"  // 0
                          "WHILE [#2 LT 3] DO2\n"  // 1
                          "WHILE [#3 LT 3] DO3\n"  // 2
                          "END3\n"                 // 3
                          "END2\n"                 // 4
                          "WHILE [#4 LT 3] DO2\n"  // 5
                          "END2\n"                 // 6
                          "END1\n"                 // 7
                          "WHILE [#5 LT 3] DO1\n"  // 8
                          "END1");                 // 9
    const auto& blocks = p.program.blocks;
    ASSERT_EQ(blocks.size(), 10u);
    const int partners[] = {7, 4, 3, 2, 1, 6, 5, 0, 9, 8};
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(blocks[i].partner, partners[i]) << "block " << i;
    }
}

TEST(Parser, IfThenAssignment) {
    Parsed p = parseClean("IF [#1 EQ 1] THEN #1=2");
    const Block& b = p.program.blocks.at(0);
    EXPECT_EQ(b.control, Control::IfThen);
    EXPECT_EQ(show(p.program, b.condition), "(#1 == 1)");
    ASSERT_EQ(b.assignments.size(), 1u);
    EXPECT_EQ(show(p.program, b.assignments[0].index), "#1");
    EXPECT_EQ(show(p.program, b.assignments[0].value), "2");
    EXPECT_EQ(b.target, kNoExpr);
}

TEST(Parser, AllComparisonSpellings) {
    struct Case {
        const char* text;
        BinaryOp op;
    } cases[] = {{"==", BinaryOp::Eq}, {"!=", BinaryOp::Ne}, {"<", BinaryOp::Lt},  {">", BinaryOp::Gt},
                 {"<=", BinaryOp::Le}, {">=", BinaryOp::Ge}, {" EQ ", BinaryOp::Eq}, {" NE ", BinaryOp::Ne},
                 {" LT ", BinaryOp::Lt}, {" GT ", BinaryOp::Gt}, {" LE ", BinaryOp::Le}, {" GE ", BinaryOp::Ge}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        Parsed p = parseClean("IF [#2" + std::string(c.text) + "3] GOTO1\nN1");
        const ExprNode& root = p.program.expressions[p.program.blocks.at(0).condition];
        ASSERT_EQ(root.kind, ExprKind::Binary);
        EXPECT_EQ(static_cast<BinaryOp>(root.op), c.op);
        EXPECT_EQ(show(p.program, root.lhs), "#2");
        EXPECT_EQ(show(p.program, root.rhs), "3");
    }
}

TEST(Parser, AndOrWrittenAsProductAndSum) {
    Parsed p = parseClean("IF [[#1 GT 0]*[#2 LT 5]] GOTO1\nIF [[#1 EQ 0]+[#2 EQ 0]] GOTO1\nN1");
    EXPECT_EQ(show(p.program, p.program.blocks[0].condition), "((#1 > 0) * (#2 < 5))");
    EXPECT_EQ(show(p.program, p.program.blocks[1].condition), "((#1 == 0) + (#2 == 0))");
}

TEST(Parser, Functions) {
    Parsed p = parseClean("#1 = ABS[-#2] + SIN[30] + COS[#3] + TAN[45]\n"
                          "#2 = SQRT[16] * ATAN[1,2]\n"
                          "#3 = FUP[1.2] - FIX[1.8] - ROUND[#4]\n"
                          "#4 = abs[round[#5/2]]");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(show(p.program, b[0].assignments[0].value), "(((ABS[-#2] + SIN[30]) + COS[#3]) + TAN[45])");
    EXPECT_EQ(show(p.program, b[1].assignments[0].value), "(SQRT[16] * ATAN[1,2])");
    EXPECT_EQ(show(p.program, b[2].assignments[0].value), "((FUP[1.2] - FIX[1.8]) - ROUND[#4])");
    EXPECT_EQ(show(p.program, b[3].assignments[0].value), "ABS[ROUND[(#5 / 2)]]");
}

TEST(Parser, ArithmeticPrecedenceAndAssociativity) {
    Parsed p = parseClean("#1 = 1 + 2 * 3 - 4 / 2\n"
                          "#2 = 8 - 2 - 1\n"
                          "#3 = [1 + 2] * 3\n"
                          "#4 = 1 + 2 == 3\n"
                          "#5 = -[1+2] * -#6\n"
                          "#6 = 2 * -3");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 6u);
    EXPECT_EQ(show(p.program, b[0].assignments[0].value), "((1 + (2 * 3)) - (4 / 2))");
    EXPECT_EQ(show(p.program, b[1].assignments[0].value), "((8 - 2) - 1)");
    EXPECT_EQ(show(p.program, b[2].assignments[0].value), "((1 + 2) * 3)");
    EXPECT_EQ(show(p.program, b[3].assignments[0].value), "((1 + 2) == 3)");
    EXPECT_EQ(show(p.program, b[4].assignments[0].value), "(-(1 + 2) * -#6)");
    EXPECT_EQ(show(p.program, b[5].assignments[0].value), "(2 * -3)");
}

TEST(Parser, ExpressionColumns) {
    Parsed p = parseClean("#1 = #2 + 3*#4");
    const Assignment& a = p.program.blocks.at(0).assignments.at(0);
    const ExprNode& sum = p.program.expressions[a.value];
    EXPECT_EQ(sum.column, 9u);
    EXPECT_EQ(p.program.expressions[sum.lhs].column, 6u);
    const ExprNode& product = p.program.expressions[sum.rhs];
    EXPECT_EQ(product.column, 12u);
    EXPECT_EQ(p.program.expressions[product.rhs].column, 13u);
}

TEST(Parser, CommentsAreSkippedAndTheFirstIsKept) {
    Parsed p = parseClean("(header only)\n"
                          "G1 X1 (first) Y2 (second)\n"
                          "G1 X1 ; M30 Y2\n"
                          "G1 X1 // M30 Y2\n"
                          "; whole line\n"
                          "// whole line\n"
                          "G0 Z5");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(letters(b[0]), "GXY");
    EXPECT_EQ(b[0].comment, "first");
    EXPECT_EQ(b[0].location.line, 2u);
    EXPECT_EQ(letters(b[1]), "GX");
    EXPECT_FALSE(b[1].programEnd);
    EXPECT_EQ(letters(b[2]), "GX");
    EXPECT_FALSE(b[2].programEnd);
    EXPECT_EQ(b[3].location.line, 7u);
}

TEST(Parser, MessageTextIsKeptWithItsAssignment) {
    Parsed p = parseClean("#1503 = 1(T[%.0f])\n#1503 = 1(X,Y,Z轴机械未全部归零!)\n#1503 = 1000");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    ASSERT_EQ(b[0].assignments.size(), 1u);
    EXPECT_EQ(show(p.program, b[0].assignments[0].index), "#1503");
    EXPECT_EQ(show(p.program, b[0].assignments[0].value), "1");
    EXPECT_TRUE(b[0].assignments[0].hasText);
    EXPECT_EQ(b[0].assignments[0].text, "T[%.0f]");
    EXPECT_EQ(b[1].assignments[0].text, "X,Y,Z轴机械未全部归零!");
    EXPECT_FALSE(b[2].assignments[0].hasText);
    EXPECT_EQ(b[2].assignments[0].text, "");
}

TEST(Parser, DwellAndVariableGCode) {
    Parsed p = parseClean("G04 P500\nG#199 X1\nM30");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(letters(b[0]), "GP");
    EXPECT_EQ(show(p.program, b[0].words[0].value), "4");
    EXPECT_EQ(show(p.program, b[0].words[1].value), "500");
    EXPECT_EQ(letters(b[1]), "GX");
    EXPECT_EQ(show(p.program, b[1].words[0].value), "#199");
    EXPECT_TRUE(b[2].programEnd);
    EXPECT_FALSE(b[1].programEnd);
}

TEST(Parser, IndirectVariables) {
    Parsed p = parseClean("#[#1+1] = #[2*#3]\n"
                          "G53 X#[1330+#1300-1] F#1311\n"
                          "#1 = ##5");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(show(p.program, b[0].assignments[0].index), "#[(#1 + 1)]");
    EXPECT_EQ(show(p.program, b[0].assignments[0].value), "#[(2 * #3)]");
    ASSERT_EQ(letters(b[1]), "GXF");
    EXPECT_EQ(show(p.program, b[1].words[1].value), "#[((1330 + #1300) - 1)]");
    EXPECT_EQ(show(p.program, b[2].assignments[0].value), "#[#5]");
}

TEST(Parser, SeveralAssignmentsAndWordsInOneBlock) {
    Parsed p = parseClean("#1=1 #2=#1*2 G1 X#1 Y#2");
    const Block& b = p.program.blocks.at(0);
    ASSERT_EQ(b.assignments.size(), 2u);
    EXPECT_EQ(show(p.program, b.assignments[1].value), "(#1 * 2)");
    EXPECT_EQ(b.assignments[1].column, 6u);
    EXPECT_EQ(letters(b), "GXY");
}

TEST(Parser, ProgramEndBlockDeleteAndPercent) {
    Parsed p = parseClean("%\n/G1 X1\nM2\nM02\nM3\nM30\n%");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 5u);
    EXPECT_TRUE(b[0].blockDelete);
    EXPECT_EQ(b[0].location.line, 2u);
    EXPECT_TRUE(b[1].programEnd);
    EXPECT_TRUE(b[2].programEnd);
    EXPECT_FALSE(b[3].programEnd);
    EXPECT_TRUE(b[4].programEnd);
    EXPECT_EQ(b[4].location.line, 6u);
}

TEST(Parser, LineNumbersAndColumnsWithBlankLinesAndCrLf) {
    Parsed p = parseClean("G1 X1\r\n\r\n   G0 Y2\r\n\tN3 M5\r\n");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0].location.line, 1u);
    EXPECT_EQ(b[0].location.column, 1u);
    EXPECT_EQ(b[1].location.line, 3u);
    EXPECT_EQ(b[1].location.column, 4u);
    EXPECT_EQ(b[2].location.line, 4u);
    EXPECT_EQ(b[2].label, 3);
    EXPECT_EQ(p.program.files.at(0).name, "test.nc");
    EXPECT_EQ(b[2].location.file, 0u);
}

TEST(Parser, OProgramsSplitIntoUnitsWithTheirOwnLabels) {
    Parsed p = parseClean("G0 X0\n"      // 0  main
                          "M98 P100\n"   // 1
                          "M30\n"        // 2
                          "\n"
                          "O100 (first)\n" // 3
                          "N1 G1 X1\n"   // 4
                          "M99\n"        // 5
                          "O200\n"       // 6
                          "N1 G1 X2\n"   // 7
                          "N2 GOTO1\n"   // 8
                          "M99");        // 9
    const Program& g = p.program;
    ASSERT_EQ(g.blocks.size(), 10u);
    ASSERT_EQ(g.units.size(), 3u);
    EXPECT_EQ(g.units[0].number, -1);
    EXPECT_EQ(g.units[0].begin, 0u);
    EXPECT_EQ(g.units[0].end, 3u);
    EXPECT_TRUE(g.units[0].labels.empty());
    EXPECT_EQ(g.units[1].number, 100);
    EXPECT_EQ(g.units[1].begin, 3u);
    EXPECT_EQ(g.units[1].end, 6u);
    EXPECT_EQ(g.units[2].number, 200);
    EXPECT_EQ(g.units[2].begin, 6u);
    EXPECT_EQ(g.units[2].end, 10u);
    EXPECT_EQ(g.blocks[3].programNumber, 100);
    EXPECT_EQ(g.blocks[3].comment, "first");
    EXPECT_EQ(g.blocks[3].location.line, 5u);
    EXPECT_EQ(g.units[1].labels.size(), 1u);
    EXPECT_EQ(g.units[1].labels.at(1), (std::vector<std::uint32_t>{4}));
    EXPECT_EQ(g.units[2].labels.at(1), (std::vector<std::uint32_t>{7}));
    EXPECT_EQ(g.units[2].labels.at(2), (std::vector<std::uint32_t>{8}));
    EXPECT_EQ(g.findUnit(100), std::optional<std::uint32_t>(1));
    EXPECT_EQ(g.findUnit(200), std::optional<std::uint32_t>(2));
    EXPECT_FALSE(g.findUnit(300).has_value());
    EXPECT_EQ(g.mainUnit(), std::optional<std::uint32_t>(0));
    EXPECT_EQ(g.unitOfBlock(2), 0u);
    EXPECT_EQ(g.unitOfBlock(5), 1u);
    EXPECT_EQ(g.unitOfBlock(9), 2u);
    EXPECT_EQ(g.findLabel(2, 1, 9), std::optional<std::uint32_t>(7)); // searched back from the start
    EXPECT_FALSE(g.findLabel(0, 1, 0).has_value());
}

TEST(Parser, TheShippedToolChangeLibraryParsesCleanly) {
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
