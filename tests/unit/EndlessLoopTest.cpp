// `DOm ... ENDm` without WHILE: an endless loop that a GOTO leaves (or the runaway guard stops), in
// both dialects, nested and mixed with WHILE loops, and what `check` says about it.

#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/common/Alarm.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;
using gcode::Control;
using gcode::DiagnosticKind;
using gcode::Dialect;
using gcode::kNoExpr;
using gcode::support::listDiagnostics;
using gcode::support::parse;
using test::lines;

void expectOnly(const gcode::support::Parsed& p, DiagnosticKind kind, std::uint32_t line, std::uint32_t column,
                const std::string& message) {
    gcode::support::expectOneDiagnostic(p, kind, line, column, message);
}

TEST(EndlessLoop, BareDoPairsWithItsEndInBothDialects) {
    for (const Dialect* dialect : {&Dialect::m350(), &Dialect::fanuc()}) {
        auto p = gcode::support::parseClean("N1 DO1\n#1 = #1 + 1\nEND1\nM30", *dialect);
        const auto& b = p.program.blocks;
        ASSERT_EQ(b.size(), 4u) << dialect->name;
        EXPECT_EQ(b[0].control, Control::While) << dialect->name;
        EXPECT_EQ(b[0].condition, kNoExpr) << dialect->name;
        EXPECT_EQ(b[0].loopId, 1) << dialect->name;
        EXPECT_EQ(b[0].label, 1) << dialect->name;
        EXPECT_EQ(b[0].partner, 2) << dialect->name;
        EXPECT_EQ(b[2].partner, 0) << dialect->name;
    }
}

TEST(EndlessLoop, GotoLeavesTheLoopOnM350) {
    auto run = test::runM350(lines({
        "#1 = 0",
        "DO1",
        "#1 = #1 + 1",
        "IF #1 >= 5 GOTO10",
        "END1",
        "#2 = 99 (never reached)",
        "N10 #3 = #1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(3), 5);
    EXPECT_DOUBLE_EQ(run.number(2), 0);
}

TEST(EndlessLoop, GotoLeavesTheLoopOnFanuc) {
    auto run = test::runFanuc(lines({
        "#1 = 0",
        "DO 2",
        "#1 = #1 + 2",
        "IF [#1 GE 8] GOTO 10",
        "END 2",
        "N10 #3 = #1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(3), 8);
}

TEST(EndlessLoop, NestsWithWhileLoops) {
    // an endless DO1 around a WHILE DO2 around an endless DO3: 4 outer passes of 3 inner passes,
    // each inner pass leaving its DO3 after two turns
    auto run = test::runFanuc(lines({
        "#1 = 0",
        "#4 = 0",
        "DO1",
        "  #2 = 0",
        "  WHILE [#2 LT 3] DO2",
        "    #5 = 0",
        "    DO3",
        "      #5 = #5 + 1",
        "      #4 = #4 + 1",
        "      IF [#5 GE 2] GOTO30",
        "    END3",
        "N30 #2 = #2 + 1",
        "  END2",
        "  #1 = #1 + 1",
        "  IF [#1 GE 4] GOTO20",
        "END1",
        "N20 M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 4);
    EXPECT_DOUBLE_EQ(run.number(4), 4 * 3 * 2);
}

TEST(EndlessLoop, RunawayGuardStopsALoopNothingLeaves) {
    controller::RunSettings settings;
    settings.maxSimTime = 0.5;
    auto run = test::runM350(lines({"#1 = 0", "DO3", "#1 = #1 + 1", "END3", "M30"}), settings);
    ASSERT_TRUE(run.report.alarm) << "an endless loop must not end by itself";
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SimulatedTimeLimit) << run.alarmText();
    EXPECT_GE(run.report.alarm->line, 2u);
    EXPECT_LE(run.report.alarm->line, 4u);
    EXPECT_GT(run.number(1), 1000); // it looped, one block time (0.1 ms) a line
}

TEST(EndlessLoop, CheckReportsAnUnclosedDo) {
    expectOnly(parse("N5 DO2\n#1 = 1", Dialect::m350()), DiagnosticKind::Flow, 1, 4, "DO2 has no END2");
    expectOnly(parse("DO1\n#1 = 1", Dialect::fanuc()), DiagnosticKind::Flow, 1, 1, "DO1 has no END1");
}

TEST(EndlessLoop, CheckReportsAnEndClosingTheWrongLoop) {
    auto p = parse("DO1\nWHILE [#1 LT 3] DO2\nEND1\nEND2", Dialect::fanuc());
    bool found = false;
    for (const gcode::Diagnostic& d : p.diagnostics) {
        if (d.line == 3) {
            found = true;
            EXPECT_EQ(d.kind, DiagnosticKind::Flow);
            EXPECT_EQ(d.column, 1u);
            EXPECT_EQ(d.message, "END1 closes the loop WHILE ... DO2 opened at line 2 (expected END2)");
        }
    }
    EXPECT_TRUE(found) << listDiagnostics(p.diagnostics);
}

TEST(EndlessLoop, CheckReportsTheSameNumberOpenTwice) {
    auto p = parse("WHILE [#1 LT 3] DO1\nDO1\nEND1\nEND1", Dialect::fanuc());
    expectOnly(p, DiagnosticKind::Flow, 2, 1, "DO1 is already open (line 1): nested loops need different numbers");
}

TEST(EndlessLoop, SyntaxErrorsNameTheColumn) {
    // the broken line still opens its loop, so its END is not reported again
    expectOnly(parse("DO1 X5\nEND1", Dialect::m350()), DiagnosticKind::Syntax, 1, 5, "unexpected 'X' after DO");
    expectOnly(parse("DO\nEND1", Dialect::m350()), DiagnosticKind::Syntax, 1, 3,
               "DO must be followed by a loop number 1-16, found the end of the line");
    auto tooHigh = parse("DO4\nEND4", Dialect::fanuc());
    ASSERT_FALSE(tooHigh.diagnostics.empty());
    EXPECT_EQ(tooHigh.diagnostics.front().kind, DiagnosticKind::Syntax);
    EXPECT_EQ(tooHigh.diagnostics.front().line, 1u);
    EXPECT_EQ(tooHigh.diagnostics.front().column, 3u);
    EXPECT_EQ(tooHigh.diagnostics.front().message, "DO4: loop numbers run from 1 to 3 in the fanuc dialect");
}

TEST(EndlessLoop, UnclosedDoAlarmsOnlyWhenReached) {
    auto run = test::runM350(lines({"#1 = 1", "GOTO9", "DO1", "#1 = 2", "N9 M30"}));
    EXPECT_RUN_OK(run);
    auto reached = test::runM350(lines({"#1 = 1", "N7 DO1", "#1 = 2", "M30"}));
    ASSERT_TRUE(reached.report.alarm);
    EXPECT_EQ(reached.report.alarm->code, AlarmCode::WhileWithoutEnd);
    EXPECT_EQ(reached.report.alarm->line, 2u);
    EXPECT_EQ(reached.report.alarm->column, 4u);
    EXPECT_EQ(reached.report.alarm->message, "DO1 has no matching END1");
}

} // namespace
