// FANUC's external output: POPEN, DPRNT[...] with its #var[cd] digit format, BPRNT[...] in binary,
// PCLOS. The statements as parsed, the records as formatted, and what a run sends to the device.
#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/macro/PrintFormat.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;
using gcode::Control;
using gcode::Dialect;
using gcode::support::listDiagnostics;
using macro::Value;
using test::lines;
using namespace std::string_literals;

// ---------------------------------------------------------------- formats

TEST(DprntFormat, SignDigitsAndPoint) {
    EXPECT_EQ(macro::formatDprnt(Value::of(128.47398), 5, 3), "   128.474");
    EXPECT_EQ(macro::formatDprnt(Value::of(-91.2), 5, 3), "-   91.200");
    EXPECT_EQ(macro::formatDprnt(Value::of(1.5436), 4, 4), "    1.5436");
    EXPECT_EQ(macro::formatDprnt(Value::of(1.5436), 0, 3), " .544"); // rounded, no integer digits
    EXPECT_EQ(macro::formatDprnt(Value::of(7.6), 3, 0), "   8");     // d = 0: no point, rounded
    EXPECT_EQ(macro::formatDprnt(Value::of(0.0), 3, 2), "   0.00");  // the units digit always shows
    EXPECT_EQ(macro::formatDprnt(Value::empty(), 2, 1), "  0.0");    // <vacant> as 0
}

TEST(DprntFormat, DigitsAboveTheFormatAreNotSent) {
    EXPECT_EQ(macro::formatDprnt(Value::of(123.456), 2, 0), " 23");
    EXPECT_EQ(macro::formatDprnt(Value::of(-98765.4), 3, 1), "-765.4");
}

TEST(DprntFormat, RoundsHalfAwayFromZeroAndDropsTheSignOfZero) {
    EXPECT_EQ(macro::formatDprnt(Value::of(2.5), 1, 0), " 3");
    EXPECT_EQ(macro::formatDprnt(Value::of(-2.5), 1, 0), "-3");
    EXPECT_EQ(macro::formatDprnt(Value::of(-0.0004), 1, 3), " 0.000");
    EXPECT_EQ(macro::formatDprnt(Value::of(9.9996), 2, 3), " 10.000");
}

TEST(BprntFormat, ThirtyTwoBitsMostSignificantFirst) {
    EXPECT_EQ(macro::formatBprnt(Value::of(318.49362), 3), std::string("\x00\x04\xDC\x1E", 4));
    EXPECT_EQ(macro::formatBprnt(Value::of(-91.2), 3), std::string("\xFF\xFE\x9B\xC0", 4));
    EXPECT_EQ(macro::formatBprnt(Value::of(23.9), 0), std::string("\x00\x00\x00\x18", 4));
    EXPECT_EQ(macro::formatBprnt(Value::empty(), 3), std::string("\x00\x00\x00\x00", 4));
    EXPECT_FALSE(macro::formatBprnt(Value::of(3.0e9), 0));
    EXPECT_FALSE(macro::formatBprnt(Value::of(2.2e6), 3));
}

// ---------------------------------------------------------------- parsing

TEST(ExternalOutputParse, DprntItemsTextAndVariables) {
    auto p = gcode::support::parseClean("POPEN\nN7 DPRNT [X#2[53]*TOOL#30 [20]] (result)\nPCLOS", Dialect::fanuc());
    const auto& b = p.program.blocks;
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0].control, Control::Popen);
    EXPECT_EQ(b[2].control, Control::Pclos);
    EXPECT_EQ(b[1].control, Control::Dprnt);
    EXPECT_EQ(b[1].label, 7);
    EXPECT_EQ(b[1].comment, "result");
    const auto items = p.program.statements[b[1].statement];
    ASSERT_EQ(items.size(), 4u);
    EXPECT_EQ(items[0].text, "X");
    EXPECT_EQ(gcode::support::show(p.program, items[1].value), "#2");
    EXPECT_EQ(items[1].integerDigits, 5);
    EXPECT_EQ(items[1].fractionDigits, 3);
    EXPECT_EQ(items[1].column, 12u);
    EXPECT_EQ(items[2].text, " TOOL"); // `*` is a space
    EXPECT_EQ(gcode::support::show(p.program, items[3].value), "#30");
    EXPECT_EQ(items[3].integerDigits, 2);
    EXPECT_EQ(items[3].fractionDigits, 0);
}

TEST(ExternalOutputParse, TextIsNoGCode) {
    // an exponent, a block comment's marks and words that are keywords are all plain text here
    auto p = gcode::support::parseClean("DPRNT[1E5*C*/X*/*END*IF*GOTO]", Dialect::fanuc());
    const auto items = p.program.statements[p.program.blocks[0].statement];
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].text, "1E5 C /X / END IF GOTO");
}

TEST(ExternalOutputParse, BprntHasOneDigitFormats) {
    auto p = gcode::support::parseClean("BPRNT[C*/X#110[3]M#112[0]]", Dialect::fanuc());
    const auto items = p.program.statements[p.program.blocks[0].statement];
    ASSERT_EQ(items.size(), 4u);
    EXPECT_EQ(items[0].text, "C /X");
    EXPECT_EQ(items[1].fractionDigits, 3);
    EXPECT_EQ(items[2].text, "M");
    EXPECT_EQ(items[3].fractionDigits, 0);
}

struct BadLine {
    const char* line;
    std::uint32_t column;
    const char* message;
};

TEST(ExternalOutputParse, ErrorsNameTheColumn) {
    const BadLine bad[] = {
        {"DPRNT[X#1]", 10, "#1 needs its digit format in brackets: #100[53] (5 integer digits, 3 decimals)"},
        {"DPRNT[X#1[5]]", 12, "the digit format of #1 is two digits, [cd]: c integer digits, d decimals"},
        {"DPRNT[X#1[55]]", 10, "#1[55]: c + d must be 1 to 8 digits"},
        {"DPRNT[X#1[00]]", 10, "#1[00]: c + d must be 1 to 8 digits"},
        {"BPRNT[X#1[53]]", 12, "missing ']' to close the digit format of #1 at column 10"},
        {"DPRNT[x#1[53]]", 7, "DPRNT text may hold capital letters"},
        {"DPRNT[X#1[53]", 14, "missing ']' to close DPRNT[ at column 6"},
        {"DPRNT[X#[1][53]]", 9, "DPRNT prints a variable by its number"},
        {"DPRNT 5", 7, "DPRNT must be followed by [...]"}, // `DPRNT X` would be one word: spaces do not count
        {"DPRNT[A] X1", 10, "unexpected 'X' after DPRNT[...] (it stands alone in its block)"},
        {"POPEN 1", 7, "unexpected '1' after POPEN (it stands alone in its block)"},
        {"G1 X1 DPRNT[A]", 7, "DPRNT must start the block (after the N number)"},
    };
    for (const BadLine& b : bad) {
        gcode::support::expectOneDiagnostic(gcode::support::parse(b.line, Dialect::fanuc()),
                                            gcode::DiagnosticKind::Syntax, 1, b.column, b.message, b.line);
    }
}

TEST(ExternalOutputParse, TheM350HasNone) {
    auto p = gcode::support::parse("N1 POPEN\nDPRNT[A]", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[0].column, 4u);
    EXPECT_EQ(p.diagnostics[0].message,
              "POPEN is FANUC's external output: the m350 dialect has no POPEN, DPRNT, BPRNT or PCLOS");
    EXPECT_EQ(p.diagnostics[1].line, 2u);
}

// ---------------------------------------------------------------- runs

TEST(ExternalOutputRun, RecordsGoToTheDevice) {
    auto run = test::runFanuc(lines({
        "#2 = 128.47398", "#5 = -91.2", "#30 = 123.456",
        "POPEN",
        "DPRNT[X#2[53]Y#5[53]T#30[20]]",
        "DPRNT[***MEASURED*DIAMETER***]",
        "DPRNT[]",
        "BPRNT[X#2[3]]",
        "PCLOS",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_TRUE(run.controller->externalDevices().outputOpened());
    EXPECT_EQ(run.controller->externalDevices().received(), "X   128.474Y-   91.200T 23\n"
                                                "   MEASURED DIAMETER   \n"
                                                "\n"
                                                "X\x00\x01\xF5\xDA\n"s);
}

TEST(ExternalOutputRun, DprntWithoutPopenAlarmsOnItsLine) {
    auto run = test::runFanuc(lines({"#1 = 1", "N20 DPRNT[A#1[10]]", "M30"}));
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::DeviceError);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.report.alarm->column, 5u);
    EXPECT_EQ(run.report.alarm->message,
              "DPRNT without POPEN: the external output device is closed (open it with POPEN before DPRNT, close "
              "it with PCLOS)");
    EXPECT_TRUE(run.controller->externalDevices().received().empty());
}

TEST(ExternalOutputRun, PclosClosesTheDevice) {
    auto run = test::runFanuc(lines({"POPEN", "DPRNT[A]", "PCLOS", "BPRNT[B]", "M30"}));
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->line, 4u);
    EXPECT_EQ(run.report.alarm->message.rfind("BPRNT without POPEN", 0), 0u) << run.report.alarm->message;
    EXPECT_EQ(run.controller->externalDevices().received(), "A\n");
}

TEST(ExternalOutputRun, BprntValueTooLargeAlarmsAtTheVariable) {
    auto run = test::runFanuc(lines({"#7 = 5000000", "POPEN", "BPRNT[X#7[3]]", "M30"}));
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::InvalidArgument);
    EXPECT_EQ(run.report.alarm->line, 3u);
    EXPECT_EQ(run.report.alarm->column, 8u);
    EXPECT_NE(run.report.alarm->message.find("does not fit in 32 bits"), std::string::npos)
        << run.report.alarm->message;
}

TEST(ExternalOutputRun, BreakRunSendsOnlyWhatComesAfterTheStartLine) {
    controller::Controller c(test::fanucMachine(), {});
    ASSERT_TRUE(c.loadFile(test::writeTempFile(lines({"POPEN", "DPRNT[A]", "G0 X1", "DPRNT[B]", "PCLOS", "M30"}))));
    Message why;
    ASSERT_TRUE(c.breakRun().startAtLine(3, &why)) << why;
    EXPECT_EQ(c.advance(100.0), controller::Controller::RunState::Finished);
    EXPECT_EQ(c.externalDevices().received(), "B\n"); // POPEN was scanned: the device is open; A is not sent again
}

} // namespace
