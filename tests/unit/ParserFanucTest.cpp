// The parser in the FANUC Custom Macro B dialect: insignificant spaces, word operators with their
// precedence, ATAN[a]/[b], the extended functions, and what FANUC rejects that the M350 accepts.

#include "core/gcode/Dialect.h"
#include "ParseSupport.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

using namespace m350::gcode;

namespace {

using support::listDiagnostics;
using support::Parsed;
using support::show;

Parsed parse(std::string_view text, const Dialect& dialect = Dialect::fanuc()) {
    return support::parse(text, dialect, "fanuc.nc");
}

Parsed parseClean(std::string_view text) {
    return support::parseClean(text, Dialect::fanuc(), "fanuc.nc");
}

std::string value(const Parsed& p, std::size_t block) {
    const Block& b = p.program.blocks.at(block);
    if (b.assignments.empty()) {
        return "<no assignment>";
    }
    return show(p.program, b.assignments[0].value);
}

const Diagnostic* onlySyntaxError(const Parsed& p) {
    EXPECT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    if (p.diagnostics.empty()) {
        return nullptr;
    }
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    return &p.diagnostics[0];
}

} // namespace

TEST(ParserFanuc, GoToWithSpaces) {
    Parsed p = parseClean("GO TO 290\nN290 M30");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0].control, Control::Goto);
    EXPECT_EQ(show(p.program, b[0].target), "290");
    EXPECT_EQ(b[1].label, 290);
    EXPECT_TRUE(b[1].programEnd);
}

TEST(ParserFanuc, IfWithBracketsAndGoToWithSpaces) {
    Parsed p = parseClean("IF [#1000 EQ 1] GO TO 290\nN290");
    const Block& b = p.program.blocks.at(0);
    EXPECT_EQ(b.control, Control::IfGoto);
    EXPECT_EQ(show(p.program, b.condition), "(#1000 == 1)");
    EXPECT_EQ(show(p.program, b.target), "290");
}

TEST(ParserFanuc, PackedIfGotoWithLabelAndComment) {
    Parsed p = parseClean("N10 IF[#1000EQ1]GO TO 290 (comment)\nN290");
    const Block& b = p.program.blocks.at(0);
    EXPECT_EQ(b.label, 10);
    EXPECT_EQ(b.control, Control::IfGoto);
    EXPECT_EQ(b.controlColumn, 5u);
    EXPECT_EQ(show(p.program, b.condition), "(#1000 == 1)");
    EXPECT_EQ(show(p.program, b.target), "290");
    EXPECT_EQ(b.comment, "comment");
    EXPECT_EQ(p.program.units.at(0).labels.count(10), 1u);
}

TEST(ParserFanuc, SpacedKeywordsInLoops) {
    Parsed p = parseClean("WH ILE [#1 LE 10] DO 1\n#1 = #1 + 1\nEN D 1\nIF [#1 GT 3] TH EN #2 = 1");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(b[0].control, Control::While);
    EXPECT_EQ(b[0].loopId, 1);
    EXPECT_EQ(show(p.program, b[0].condition), "(#1 <= 10)");
    EXPECT_EQ(b[2].control, Control::End);
    EXPECT_EQ(b[0].partner, 2);
    EXPECT_EQ(b[3].control, Control::IfThen);
}

TEST(ParserFanuc, WordOperatorPrecedence) {
    Parsed p = parseClean("#1 = 1 OR 2 AND 3\n"
                          "#2 = 7 MOD 4 + 1\n"
                          "#3 = 1 XOR 2 * 3\n"
                          "#4 = 8 / 2 MOD 3\n"
                          "#5 = 1 AND 2 OR 3 AND 4\n"
                          "#6 = 1 + 2 XOR 3 - 4\n"
                          "#7 = #1 MOD #2 AND #3");
    EXPECT_EQ(value(p, 0), "(1 OR (2 AND 3))");
    EXPECT_EQ(value(p, 1), "((7 MOD 4) + 1)");
    EXPECT_EQ(value(p, 2), "(1 XOR (2 * 3))");
    EXPECT_EQ(value(p, 3), "((8 / 2) MOD 3)");
    EXPECT_EQ(value(p, 4), "((1 AND 2) OR (3 AND 4))");
    EXPECT_EQ(value(p, 5), "(((1 + 2) XOR 3) - 4)");
    EXPECT_EQ(value(p, 6), "((#1 MOD #2) AND #3)");
}

TEST(ParserFanuc, WordOperatorsBindTighterThanComparisons) {
    Parsed p = parseClean("IF [[#1 EQ 1] OR [#2 EQ 2]] GOTO 5\nIF [#1 AND 3 NE 0] GOTO 5\nN5");
    EXPECT_EQ(show(p.program, p.program.blocks[0].condition), "((#1 == 1) OR (#2 == 2))");
    EXPECT_EQ(show(p.program, p.program.blocks[1].condition), "((#1 AND 3) != 0)");
}

TEST(ParserFanuc, KeywordsInAnyCase) {
    Parsed p = parseClean("while [#1 lt 3] do1\n#1 = abs[#1] + 1\nEnd1\nif [#1 Eq 3] goto 5\nN5");
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 5u);
    EXPECT_EQ(b[0].control, Control::While);
    EXPECT_EQ(b[0].partner, 2);
    EXPECT_EQ(show(p.program, b[0].condition), "(#1 < 3)");
    EXPECT_EQ(value(p, 1), "(ABS[#1] + 1)");
    EXPECT_EQ(b[3].control, Control::IfGoto);
}

TEST(ParserFanuc, AtanWithSlash) {
    Parsed p = parseClean("#1 = ATAN[#1]/[#2]\n#2 = ATAN [#3] / [#4] * 2\n#3 = ATAN[1,2]");
    EXPECT_EQ(value(p, 0), "ATAN[#1,#2]");
    EXPECT_EQ(value(p, 1), "(ATAN[#3,#4] * 2)");
    EXPECT_EQ(value(p, 2), "ATAN[1,2]");
}

TEST(ParserFanuc, AtanWithOneArgument) {
    Parsed p = parseClean("#1 = ATAN[#1]\n#2 = ATAN[#3] * 2\n#3 = ATAN[1]/2");
    EXPECT_EQ(value(p, 0), "ATAN[#1]");
    EXPECT_EQ(value(p, 1), "(ATAN[#3] * 2)");
    EXPECT_EQ(value(p, 2), "(ATAN[1] / 2)"); // only /[b] is the second argument
}

TEST(ParserFanuc, ExtendedFunctionsAreAccepted) {
    Parsed p = parseClean("#1 = ASIN[0.5] + ACOS[#2]\n#2 = LN[#3] * EXP[1]\n#3 = BIN[#4] + BCD[#5]");
    EXPECT_EQ(value(p, 0), "(ASIN[0.5] + ACOS[#2])");
    EXPECT_EQ(value(p, 1), "(LN[#3] * EXP[1])");
    EXPECT_EQ(value(p, 2), "(BIN[#4] + BCD[#5])");
}

TEST(ParserFanuc, ExtendedFunctionsAreRejectedOnM350) {
    const char* names[] = {"ASIN", "ACOS", "LN", "EXP", "BIN", "BCD"};
    for (const char* name : names) {
        SCOPED_TRACE(name);
        Parsed p = parse("#1 = " + std::string(name) + "[1]", Dialect::m350());
        const Diagnostic* d = onlySyntaxError(p);
        ASSERT_NE(d, nullptr);
        EXPECT_EQ(d->message, std::string(name) + " is not a function of the m350 dialect");
        EXPECT_EQ(d->column, 6u);
    }
}

TEST(ParserFanuc, BracketlessConditionsAreRejected) {
    Parsed p = parse("IF #1 EQ 1 GOTO 5\nN5");
    const Diagnostic* d = onlySyntaxError(p);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->line, 1u);
    EXPECT_EQ(d->column, 4u);
    EXPECT_EQ(d->message, "the IF condition must be in brackets: IF [...]");

    Parsed w = parse("WHILE #1 LT 3 DO1\nEND1");
    const Diagnostic* dw = onlySyntaxError(w); // the END1 is not reported again
    ASSERT_NE(dw, nullptr);
    EXPECT_EQ(dw->column, 7u);
    EXPECT_EQ(dw->message, "the WHILE condition must be in brackets: WHILE [...]");
}

TEST(ParserFanuc, VariableGCodes) {
    Parsed p = parseClean("G#199 G#198 G#197");
    const Block& b = p.program.blocks.at(0);
    ASSERT_EQ(b.words.size(), 3u);
    const char* expected[] = {"#199", "#198", "#197"};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(b.words[i].letter, 'G');
        EXPECT_EQ(show(p.program, b.words[i]), expected[i]);
    }
    EXPECT_EQ(b.words[2].column, 13u);
}

TEST(ParserFanuc, CStyleComparisonsAreRejectedWithTheWordToWrite) {
    struct Case {
        const char* op;
        const char* word;
    } cases[] = {{"==", "EQ"}, {"!=", "NE"}, {"<", "LT"}, {">", "GT"}, {"<=", "LE"}, {">=", "GE"}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.op);
        Parsed p = parse("IF [#1 " + std::string(c.op) + " 1] GOTO 5\nN5");
        const Diagnostic* d = onlySyntaxError(p);
        ASSERT_NE(d, nullptr);
        EXPECT_EQ(d->column, 8u);
        EXPECT_EQ(d->message, "'" + std::string(c.op) + "' is not fanuc syntax: write " + c.word);
    }
}

TEST(ParserFanuc, LoopNumbersRunFromOneToThree) {
    Parsed ok = parseClean("WHILE [#1 LT 3] DO3\nEND3");
    EXPECT_EQ(ok.program.blocks.at(0).loopId, 3);
    EXPECT_EQ(ok.program.blocks.at(0).partner, 1);

    Parsed p = parse("WHILE [#1 LT 3] DO4\nEND4");
    ASSERT_GE(p.diagnostics.size(), 1u);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Syntax);
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[0].column, 19u);
    EXPECT_EQ(p.diagnostics[0].message, "DO4: loop numbers run from 1 to 3 in the fanuc dialect");
    for (const Diagnostic& d : p.diagnostics) {
        EXPECT_EQ(d.kind, DiagnosticKind::Syntax) << formatDiagnostic(d); // no pairing cascade
    }
}

TEST(ParserFanuc, SlashSlashIsNotAComment) {
    Parsed p = parse("G1 X1 // X2");
    const Diagnostic* d = onlySyntaxError(p);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->column, 7u);
    EXPECT_EQ(d->message, "arithmetic in an address value needs brackets: X[...]"); // `/` is division here
}

TEST(ParserFanuc, SemicolonEndsTheBlock) {
    Parsed p = parseClean("G1 X1 ; Y2 junk\n#1 = 2 ;");
    ASSERT_EQ(p.program.blocks.size(), 2u);
    EXPECT_EQ(p.program.blocks[0].words.size(), 2u);
    EXPECT_EQ(value(p, 1), "2");
}

TEST(ParserFanuc, MacroCallProgramWithUnits) {
    Parsed p = parseClean("G65 P9010 A1 B2\nM30\nO9010\nN1 #3 = #1 + #2\nIF [#3 GT 2] GOTO 1\nM99");
    const Program& g = p.program;
    ASSERT_EQ(g.units.size(), 2u);
    EXPECT_EQ(g.units[1].number, 9010);
    EXPECT_EQ(g.units[1].labels.at(1), (std::vector<std::uint32_t>{3}));
    EXPECT_EQ(g.blocks[0].words.size(), 4u);
}

TEST(ParserFanuc, CallToAMissingProgramIsAFlowError) {
    Parsed p = parse("G65 P9011 A1\nM30");
    ASSERT_EQ(p.diagnostics.size(), 1u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].kind, DiagnosticKind::Flow);
    EXPECT_EQ(p.diagnostics[0].column, 5u);
    EXPECT_EQ(p.diagnostics[0].message, "no O9011 in this file or the machine's macro libraries");
}
