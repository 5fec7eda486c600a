// The parser on well-formed M350 programs: the structure of blocks, words, assignments, control
// statements and expression trees, and how a file is split into O-program units.

#include "ParseSupport.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

using namespace m350::gcode;

namespace {

using support::Parsed;
using support::show;

Parsed parseClean(std::string_view text) {
    return support::parseClean(text, Dialect::m350());
}

std::string letters(const Block& block) {
    std::string out;
    for (const Word& w : block.words) {
        out += w.letter;
    }
    return out;
}

// The words' values as show() renders them.
std::vector<std::string> values(const Program& program, const Block& block) {
    std::vector<std::string> out;
    for (const Word& w : block.words) {
        out.push_back(show(program, w));
    }
    return out;
}

// The value assigned by the first assignment of block `index`.
std::string assigned(const Parsed& p, std::size_t index) {
    const Block& b = p.program.blocks.at(index);
    return b.assignments.empty() ? "<no assignment>" : show(p.program, b.assignments[0].value);
}

// Every block's WHILE/END partner, -1 for the others.
std::vector<int> partners(const Program& program) {
    std::vector<int> out;
    for (const Block& b : program.blocks) {
        out.push_back(b.partner);
    }
    return out;
}

} // namespace

TEST(Parser, PackedWordsWithVariablesAndIndirection) {
    Parsed p = parseClean("G91G31X-#2Y#3 F#22 P#[1045+#1*3] L#28 K0 Q1");
    ASSERT_EQ(p.program.blocks.size(), 1u);
    const Block& b = p.program.blocks[0];
    ASSERT_EQ(letters(b), "GGXYFPLKQ");
    const Program& g = p.program;
    EXPECT_EQ(values(g, b), (std::vector<std::string>{"91", "31", "-#2", "#3", "#22", "#[(1045 + (#1 * 3))]",
                                                      "#28", "0", "1"}));
    EXPECT_TRUE(b.words[0].isNumber());
    EXPECT_EQ(g.expressions[b.words[2].value].kind, ExprKind::Unary);
    const ExprNode& pValue = g.expressions[b.words[5].value];
    EXPECT_EQ(pValue.kind, ExprKind::Variable);
    ASSERT_NE(pValue.lhs, kNoExpr);
    EXPECT_EQ(g.expressions[pValue.lhs].kind, ExprKind::Binary);
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
    EXPECT_TRUE(b.words[0].isNumber()); // kept in the word: no expression node
    EXPECT_TRUE(b.words[1].isNumber());
    EXPECT_FALSE(b.words[2].isNumber());
    EXPECT_EQ(values(p.program, b), (std::vector<std::string>{"-5", "2.5", "-#2", "-(#1 + 1)"}));
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
    EXPECT_EQ(blocks[0].controlColumn, 4u);
    const char* targets[] = {"7", "(#1 + 2)", "#5"};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(blocks[i].control, Control::Goto);
        EXPECT_EQ(show(p.program, blocks[i].target), targets[i]);
    }
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
    EXPECT_EQ(partners(p.program), (std::vector<int>{2, -1, 0, 5, -1, 3}));
    EXPECT_EQ(blocks[0].control, Control::While);
    EXPECT_EQ(blocks[0].loopId, 16);
    EXPECT_EQ(show(p.program, blocks[0].condition), "(#1 < 10)");
    EXPECT_EQ(blocks[2].control, Control::End);
    EXPECT_EQ(blocks[2].loopId, 16);
    EXPECT_EQ(blocks[3].label, 1);
    EXPECT_EQ(blocks[3].control, Control::While);
    EXPECT_EQ(blocks[3].controlColumn, 3u);
    EXPECT_EQ(blocks[3].loopId, 13);
    EXPECT_EQ(show(p.program, blocks[3].condition), "(#13 > 0)");
}

TEST(Parser, NestedAndSequentialLoopsPair) {
    Parsed p = parseClean("WHILE [#1 LT 3] DO1\n" // 0
                          "WHILE [#2 LT 3] DO2\n" // 1
                          "WHILE [#3 LT 3] DO3\n" // 2
                          "END3\n"                // 3
                          "END2\n"                // 4
                          "WHILE [#4 LT 3] DO2\n" // 5
                          "END2\n"                // 6
                          "END1\n"                // 7
                          "WHILE [#5 LT 3] DO1\n" // 8
                          "END1");                // 9
    EXPECT_EQ(partners(p.program), (std::vector<int>{7, 4, 3, 2, 1, 6, 5, 0, 9, 8}));
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
    } cases[] = {{"==", BinaryOp::Eq},   {"!=", BinaryOp::Ne},   {"<", BinaryOp::Lt},
                 {">", BinaryOp::Gt},    {"<=", BinaryOp::Le},   {">=", BinaryOp::Ge},
                 {" EQ ", BinaryOp::Eq}, {" NE ", BinaryOp::Ne}, {" LT ", BinaryOp::Lt},
                 {" GT ", BinaryOp::Gt}, {" LE ", BinaryOp::Le}, {" GE ", BinaryOp::Ge}};
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
                          "#4 = ABS[ROUND[#5/2]]");
    ASSERT_EQ(p.program.blocks.size(), 4u);
    EXPECT_EQ(assigned(p, 0), "(((ABS[-#2] + SIN[30]) + COS[#3]) + TAN[45])");
    EXPECT_EQ(assigned(p, 1), "(SQRT[16] * ATAN[1,2])");
    EXPECT_EQ(assigned(p, 2), "((FUP[1.2] - FIX[1.8]) - ROUND[#4])");
    EXPECT_EQ(assigned(p, 3), "ABS[ROUND[(#5 / 2)]]");
}

TEST(Parser, ArithmeticPrecedenceAndAssociativity) {
    Parsed p = parseClean("#1 = 1 + 2 * 3 - 4 / 2\n"
                          "#2 = 8 - 2 - 1\n"
                          "#3 = [1 + 2] * 3\n"
                          "#4 = 1 + 2 == 3\n"
                          "#5 = -[1+2] * -#6\n"
                          "#6 = 2 * -3");
    ASSERT_EQ(p.program.blocks.size(), 6u);
    EXPECT_EQ(assigned(p, 0), "((1 + (2 * 3)) - (4 / 2))");
    EXPECT_EQ(assigned(p, 1), "((8 - 2) - 1)");
    EXPECT_EQ(assigned(p, 2), "((1 + 2) * 3)");
    EXPECT_EQ(assigned(p, 3), "((1 + 2) == 3)");
    EXPECT_EQ(assigned(p, 4), "(-(1 + 2) * -#6)");
    EXPECT_EQ(assigned(p, 5), "(2 * -3)");
}

TEST(Parser, ExpressionColumns) {
    Parsed p = parseClean("#1 = #2 + 3*#4");
    const Assignment& a = p.program.blocks.at(0).assignments[0];
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
    EXPECT_EQ(letters(b[0]) + " " + letters(b[1]) + " " + letters(b[2]) + " " + letters(b[3]),
              "GXY GX GX GZ");
    EXPECT_EQ(b[0].comment, "first");
    EXPECT_FALSE(b[1].programEnd || b[2].programEnd);
    EXPECT_EQ(b[0].location.line, 2u);
    EXPECT_EQ(b[3].location.line, 7u);
}

TEST(Parser, MessageTextIsKeptWithItsAssignment) {
    Parsed p = parseClean("#1503 = 1(T[%.0f])\n#1503 = 1(X,Y,Z轴机械未全部归零!)\n#1503 = 1000");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(show(p.program, b[0].assignments[0].index), "#1503");
    EXPECT_EQ(assigned(p, 0), "1");
    EXPECT_TRUE(b[0].assignments[0].hasText);
    EXPECT_EQ(b[0].assignments[0].text, "T[%.0f]");
    EXPECT_EQ(b[1].assignments[0].text, "X,Y,Z轴机械未全部归零!");
    EXPECT_FALSE(b[2].assignments[0].hasText);
}

TEST(Parser, DwellAndVariableGCode) {
    Parsed p = parseClean("G04 P500\nG#199 X1\nM30");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(letters(b[0]), "GP");
    EXPECT_EQ(values(p.program, b[0]), (std::vector<std::string>{"4", "500"}));
    EXPECT_EQ(letters(b[1]), "GX");
    EXPECT_EQ(values(p.program, b[1]), (std::vector<std::string>{"#199", "1"}));
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
    EXPECT_EQ(values(p.program, b[1]), (std::vector<std::string>{"53", "#[((1330 + #1300) - 1)]", "#1311"}));
    EXPECT_EQ(assigned(p, 2), "#[#5]");
}

TEST(Parser, SeveralAssignmentsAndWordsInOneBlock) {
    Parsed p = parseClean("#1=1 #2=#1*2 G1 X#1 Y#2");
    const Block& b = p.program.blocks.at(0);
    ASSERT_EQ(b.assignments.size(), 2u);
    EXPECT_EQ(assigned(p, 0), "1");
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
    EXPECT_EQ((std::vector<bool>{b[1].programEnd, b[2].programEnd, b[3].programEnd, b[4].programEnd}),
              (std::vector<bool>{true, true, false, true}));
    EXPECT_EQ(b[4].location.line, 6u);
}

TEST(Parser, LineNumbersAndColumnsWithBlankLinesAndCrLf) {
    Parsed p = parseClean("G1 X1\r\n\r\n   G0 Y2\r\n\tN3 M5\r\n");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0].location.line, 1u);
    EXPECT_EQ(b[1].location.line, 3u);
    EXPECT_EQ(b[1].location.column, 4u);
    EXPECT_EQ(b[2].location.line, 4u);
    EXPECT_EQ(b[2].label, 3);
    EXPECT_EQ(p.program.files.at(0).name, "test.nc");
    EXPECT_EQ(b[2].location.file, 0u);
}

TEST(Parser, OProgramsSplitIntoUnitsWithTheirOwnLabels) {
    Parsed p = parseClean("G0 X0\n"    // 0  main
                          "M98 P100\n" // 1
                          "M30\n"      // 2
                          "\n"
                          "O100 (first)\n" // 3
                          "N1 G1 X1\n"     // 4
                          "M99\n"          // 5
                          "O200\n"         // 6
                          "N1 G1 X2 M9\n"  // 7 (M9: not a loop without an exit)
                          "N2 GOTO1\n"     // 8
                          "M99");          // 9
    const Program& g = p.program;
    ASSERT_EQ(g.blocks.size(), 10u);
    std::string units;
    for (const ProgramUnit& u : g.units) {
        units += std::to_string(u.number) + ":" + std::to_string(u.begin) + "-" + std::to_string(u.end) + " ";
    }
    ASSERT_EQ(units, "-1:0-3 100:3-6 200:6-10 ");
    EXPECT_TRUE(g.units[0].labels.empty());
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
