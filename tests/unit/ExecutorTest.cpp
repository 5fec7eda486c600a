// Control flow and calls: IF/GOTO/WHILE, M98/G65/M99, T-code and handler calls, local levels, the
// FANUC argument specification, modal-group variables and vacant addresses.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <string>

using m350::AlarmCode;
using m350::controller::RunStatus;
using m350::test::lines;
using m350::test::loadProgram;
using m350::test::runFanuc;
using m350::test::runM350;
using m350::test::runProgram;

namespace {

// ---------------------------------------------------------------- M350: flow

TEST(ExecutorM350, IfGotoLoopSumsOneToTen) {
    auto run = runM350(lines({
        "#1 = 0",
        "#2 = 1",
        "N10 IF [#2 > 10] GOTO 20",
        "#1 = #1 + #2",
        "#2 = #2 + 1",
        "GOTO 10",
        "N20 M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 55);
    EXPECT_DOUBLE_EQ(run.number(2), 11);
}

TEST(ExecutorM350, UnbracketedConditionsAsTheFactoryMacrosWriteThem) {
    auto run = runM350(lines({
        "#13 = 4",
        "#14 = 0",
        "WHILE#13>0DO13",
        "#14 = #14 + #13",
        "#13 = #13 - 1",
        "END13",
        "IF#14 != 10 GOTO56",
        "#15 = 1",
        "N56 M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(14), 10);
    EXPECT_DOUBLE_EQ(run.number(15), 1);
}

TEST(ExecutorM350, ComputedGotoTargets) {
    auto run = runM350(lines({
        "#1 = 30",
        "GOTO #1",
        "#2 = 1",
        "N30 #3 = 1",
        "GOTO [#1 + 10]",
        "#4 = 1",
        "N40 #5 = 1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(2), 0);
    EXPECT_DOUBLE_EQ(run.number(3), 1);
    EXPECT_DOUBLE_EQ(run.number(4), 0);
    EXPECT_DOUBLE_EQ(run.number(5), 1);
}

TEST(ExecutorM350, NestedWhileLoopsUpToDo16) {
    auto run = runM350(lines({
        "#1 = 0",
        "#2 = 0",
        "WHILE [#2 < 3] DO1",
        "#3 = 0",
        "WHILE [#3 < 4] DO16",
        "#1 = #1 + 1",
        "#3 = #3 + 1",
        "END16",
        "#2 = #2 + 1",
        "END1",
        "WHILE [#2 > 100] DO2", // false at once: the body never runs
        "#4 = 1",
        "END2",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 12);
    EXPECT_DOUBLE_EQ(run.number(2), 3);
    EXPECT_DOUBLE_EQ(run.number(4), 0);
}

TEST(ExecutorM350, LoopNumberAbove16IsRejected) {
    auto run = loadProgram(m350::test::m350Machine(), lines({"WHILE [1] DO17", "END17", "M30"}));
    EXPECT_FALSE(run.loaded);
}

TEST(ExecutorM350, IfThenAssignsOnlyWhenTrue) {
    auto run = runM350(lines({"#1 = 2", "IF [#1 == 2] THEN #2 = 5", "IF [#1 != 2] THEN #3 = 5", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(2), 5);
    EXPECT_DOUBLE_EQ(run.number(3), 0);
}

// ---------------------------------------------------------------- M350: calls

TEST(ExecutorM350, M98AndG65RepeatL) {
    auto run = runM350(lines({"M98 P100 L3", "#101 = #100", "G65 P100 L2", "M98 P100", "M30",
                              "O100", "#100 = #100 + 1", "M99"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(101), 3);
    EXPECT_DOUBLE_EQ(run.number(100), 6);
}

std::string argumentCopier(int number) {
    // copies #1..#17 to #101..#117 with an indirect loop
    return lines({"O" + std::to_string(number), "#30 = 1", "WHILE [#30 <= 17] DO1", "#[100 + #30] = #[#30]",
                  "#30 = #30 + 1", "END1", "M99"});
}

TEST(ExecutorM350, CallArgumentLettersMapToLocals) {
    for (const char* call : {"M98 P100", "G65 P100"}) {
        auto run = runM350(lines({std::string(call) + " X1 Y2 Z3 A4 B5 C6 I7 J8 K9 R10 H12 Q14 D15 F16 S17", "M30"}) +
                           argumentCopier(100));
        EXPECT_RUN_OK(run);
        for (int local = 1; local <= 17; ++local) {
            double expected = (local == 11 || local == 13) ? 0 : local; // no letter maps to #11 or #13
            EXPECT_DOUBLE_EQ(run.number(100 + local), expected) << call << ": #" << local;
        }
    }
}

// Every call opens a local level #0-#49; the caller's locals are back after the return.
TEST(ExecutorM350, EveryCallOpensAFreshLocalLevel) {
    struct Form {
        const char* call;
        int program;
    };
    for (Form form : {Form{"M98 P100 X5", 100}, Form{"G65 P100 X5", 100}, Form{"T5", 20000},
                      Form{"M100 X5", 10100}}) {
        auto run = runM350(lines({
            "#0 = 2", "#1 = 11", "#30 = 7", "#49 = 3",
            form.call,
            "#70 = #0", "#71 = #1", "#72 = #30", "#73 = #49",
            "M30",
            "O" + std::to_string(form.program),
            "#60 = #1", "#61 = #30", "#62 = #49", "#63 = #0",
            "#0 = 97", "#1 = 98", "#30 = 99", "#49 = 96",
            "M98 P200 X6",
            "#64 = #1", "#65 = #30",
            "M99",
            "O200",
            "#66 = #1", "#1 = 77", "#30 = 78",
            "M99",
        }));
        EXPECT_RUN_OK(run);
        SCOPED_TRACE(form.call);
        EXPECT_DOUBLE_EQ(run.number(60), 5);  // the argument
        EXPECT_DOUBLE_EQ(run.number(61), 0);  // fresh level: the caller's #30 is not visible
        EXPECT_DOUBLE_EQ(run.number(62), 0);
        EXPECT_DOUBLE_EQ(run.number(63), 0);
        EXPECT_DOUBLE_EQ(run.number(66), 6);  // the nested call's argument
        EXPECT_DOUBLE_EQ(run.number(64), 98); // the nested call did not touch this level
        EXPECT_DOUBLE_EQ(run.number(65), 99);
        EXPECT_DOUBLE_EQ(run.number(70), 2);  // main's locals are back
        EXPECT_DOUBLE_EQ(run.number(71), 11);
        EXPECT_DOUBLE_EQ(run.number(72), 7);
        EXPECT_DOUBLE_EQ(run.number(73), 3);
    }
}

TEST(ExecutorM350, GCodeHandlerGetsXYZAsLocalsZeroOneTwo) {
    auto run = runM350(lines({"#0 = 1", "#1 = 2", "#2 = 3", "G100 X7 Y8 Z9 I4", "#70 = #0", "#71 = #1", "#72 = #2",
                              "M30", "O9100", "#60 = #0", "#61 = #1", "#62 = #2", "#63 = #7", "M99"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 7);
    EXPECT_DOUBLE_EQ(run.number(61), 8);
    EXPECT_DOUBLE_EQ(run.number(62), 9);
    EXPECT_DOUBLE_EQ(run.number(63), 4);
    EXPECT_DOUBLE_EQ(run.number(70), 1);
    EXPECT_DOUBLE_EQ(run.number(71), 2);
    EXPECT_DOUBLE_EQ(run.number(72), 3);
}

TEST(ExecutorM350, M99PReturnsToALabelOfTheCaller) {
    auto run = runM350(lines({"M98 P100", "#60 = 1", "N7 #61 = 2", "M30", "O100", "#62 = 3", "M99 P7", "#63 = 4"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 0);
    EXPECT_DOUBLE_EQ(run.number(61), 2);
    EXPECT_DOUBLE_EQ(run.number(62), 3);
    EXPECT_DOUBLE_EQ(run.number(63), 0);
}

TEST(ExecutorM350, TheEndOfAnOProgramReturnsLikeM99) {
    auto run = runM350(lines({"M98 P100", "#61 = 2", "M30", "O100", "#60 = 1", "O200", "#62 = 3"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 1);
    EXPECT_DOUBLE_EQ(run.number(61), 2);
    EXPECT_DOUBLE_EQ(run.number(62), 0);
}

// `T5` is `M98 P20000 X5` with #1504 = 5; the program's own O20000 wins over the library's.
TEST(ExecutorM350, TWordRunsTheUsersOwnO20000) {
    auto run = runProgram(m350::test::bundledMachine(), lines({
        "#1 = 42",
        "T5",
        "#70 = #1",
        "M30",
        "O20000",
        "#60 = #1",
        "#61 = #1504",
        "#62 = #62 + 1",
        "M99",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 5);
    EXPECT_DOUBLE_EQ(run.number(61), 5);
    EXPECT_DOUBLE_EQ(run.number(1504), 5);
    EXPECT_DOUBLE_EQ(run.number(62), 1);
    EXPECT_DOUBLE_EQ(run.number(70), 42);
    // the library's tool change did not run: tool 1 is still in the spindle, nothing moved
    EXPECT_DOUBLE_EQ(run.number(1300), 1);
    EXPECT_EQ(run.report.tool, 1);
    EXPECT_DOUBLE_EQ(run.report.machine(0), 0);
    EXPECT_DOUBLE_EQ(run.report.machine(1), 0);
    EXPECT_DOUBLE_EQ(run.report.machine(2), 0);
}

TEST(ExecutorM350, TWordWithExpressionValue) {
    auto run = runM350(lines({"#50 = 3", "T[#50 + 1]", "M30", "O20000", "#60 = #1", "M99"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 4);
    EXPECT_DOUBLE_EQ(run.number(1504), 4);
}

// ---------------------------------------------------------------- FANUC: calls and locals

TEST(ExecutorFanuc, M98SharesTheCallersLocalsG65OpensANewLevel) {
    auto run = runFanuc(lines({
        "#1 = 5",
        "M98 P100",
        "#101 = #1",   // M98: the subprogram changed the caller's #1
        "G65 P200 A9",
        "#102 = #1",   // G65: the macro's #1 was its own
        "#103 = #2",
        "M30",
        "O100",
        "#1 = #1 + 1",
        "M99",
        "O200",
        "#110 = #1",
        "#111 = #2",
        "#1 = 50",
        "#2 = 51",
        "M99",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(101), 6);
    EXPECT_DOUBLE_EQ(run.number(110), 9);
    EXPECT_TRUE(run.vacant(111));
    EXPECT_DOUBLE_EQ(run.number(102), 6);
    EXPECT_TRUE(run.vacant(103));
}

std::string fanucCopier() {
    return lines({"O9100", "#30 = 1", "WHILE [#30 LE 26] DO1", "#[100 + #30] = #[#30]", "#30 = #30 + 1", "END1",
                  "M99"});
}

TEST(ExecutorFanuc, G65ArgumentSpecificationI) {
    auto run = runFanuc(lines({"G65 P9100 A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 Q17 R18 S19 U21 V22 W23 X24 Y25 Z26",
                               "M30"}) + fanucCopier());
    EXPECT_RUN_OK(run);
    for (int local : {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 17, 18, 19, 21, 22, 23, 24, 25, 26}) {
        EXPECT_FALSE(run.vacant(100 + local)) << "#" << local;
        EXPECT_DOUBLE_EQ(run.number(100 + local), local) << "#" << local;
    }
    for (int unused : {10, 12, 14, 15, 16}) {
        EXPECT_TRUE(run.vacant(100 + unused)) << "#" << unused << " has no letter and stays vacant";
    }
}

TEST(ExecutorFanuc, G65ArgumentsMAndTAreLocals13And20) {
    auto run = runFanuc(lines({"G65 P9100 M13 T20 A1", "M30"}) + fanucCopier());
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(101), 1);
    EXPECT_FALSE(run.vacant(113)) << "M of a G65 block is argument #13";
    EXPECT_DOUBLE_EQ(run.number(113), 13);
    EXPECT_FALSE(run.vacant(120)) << "T of a G65 block is argument #20";
    EXPECT_DOUBLE_EQ(run.number(120), 20);
}

TEST(ExecutorFanuc, LoopsNestDo1ToDo3AndDo4IsRejected) {
    auto run = runFanuc(lines({
        "#1 = 0", "#2 = 0",
        "WHILE [#2 LT 2] DO1", "#3 = 0",
        "WHILE [#3 LT 3] DO2", "#4 = 0",
        "WHILE [#4 LT 4] DO3", "#1 = #1 + 1", "#4 = #4 + 1", "END3",
        "#3 = #3 + 1", "END2",
        "#2 = #2 + 1", "END1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 24);
    auto rejected = loadProgram(m350::test::fanucMachine(), lines({"WHILE [1 EQ 1] DO4", "END4", "M30"}));
    EXPECT_FALSE(rejected.loaded);
}

TEST(ExecutorFanuc, GotoSearchesBothDirectionsAndM99P) {
    auto run = runFanuc(lines({
        "#1 = 0",
        "N1 #1 = #1 + 1",
        "IF [#1 LT 3] GOTO 1",
        "M98 P100",
        "#2 = 1",
        "N9 #3 = 1",
        "M30",
        "O100",
        "M99 P9",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 3);
    EXPECT_TRUE(run.vacant(2));
    EXPECT_DOUBLE_EQ(run.number(3), 1);
}

TEST(ExecutorFanuc, Alarm3000StopsWithTheText) {
    auto run = runFanuc(lines({"#100 = 1", "#3000=1(TOOL NOT FOUND)", "#101 = 1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::MacroAlarm);
    EXPECT_NE(run.report.alarm->message.find("TOOL NOT FOUND"), std::string::npos) << run.report.alarm->message;
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.report.alarm->file, run.fileName);
    EXPECT_DOUBLE_EQ(run.number(100), 1);
    EXPECT_TRUE(run.vacant(101));
}

TEST(ExecutorM350, Alarm3000StopsWithTheTextToo) {
    // a simulator extra on the M350 (its firmware has no #3000): our tool-setting macros use it
    auto run = runM350(lines({"#100 = 1", "#3000=4(固定对刀仪无效!)", "#101 = 1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::MacroAlarm);
    EXPECT_EQ(run.report.alarm->message, "macro alarm 3004: 固定对刀仪无效!");
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.number(101), 0.0);
}

TEST(ExecutorFanuc, ModalGroupVariablesFollowTheModalState) {
    auto run = runFanuc(lines({
        "#101 = #4001", "#103 = #4003", "#106 = #4006",
        "#199 = #4003",
        "G91 G20 G01 F10",
        "#111 = #4001", "#113 = #4003", "#116 = #4006",
        "G#199 G21", // restores the saved G90
        "#123 = #4003", "#126 = #4006",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(101), 0);
    EXPECT_DOUBLE_EQ(run.number(103), 90);
    EXPECT_DOUBLE_EQ(run.number(106), 21);
    EXPECT_DOUBLE_EQ(run.number(111), 1);
    EXPECT_DOUBLE_EQ(run.number(113), 91);
    EXPECT_DOUBLE_EQ(run.number(116), 20);
    EXPECT_DOUBLE_EQ(run.number(123), 90);
    EXPECT_DOUBLE_EQ(run.number(126), 21);
}

TEST(ExecutorFanuc, ModalGroupVariablesAreReadOnly) {
    auto run = runFanuc(lines({"#100 = 1", "#4003 = 91", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::ReadOnlyVariable);
    EXPECT_EQ(run.report.alarm->line, 2u);
}

TEST(ExecutorFanuc, AddressWithVacantValueIsOmitted) {
    auto run = runFanuc(lines({
        "G90 G00 X10 Y20 Z5",
        "X#10 Y#11 Z-1", // #10 and #11 vacant: X and Y do not move
        "#12 = 0",
        "Y#12",          // 0 is not vacant: Y moves to 0
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.report.machine(0), 10);
    EXPECT_DOUBLE_EQ(run.report.machine(1), 0);
    EXPECT_DOUBLE_EQ(run.report.machine(2), -1);
    EXPECT_DOUBLE_EQ(run.number(5021), 10);
    EXPECT_DOUBLE_EQ(run.number(5023), -1);
}

TEST(ExecutorFanuc, NullVariableIsAlwaysVacantAndReadOnly) {
    auto run = runFanuc(lines({"#1 = #0", "#2 = [#0 EQ #0]", "#100 = 3", "#0 = 5", "#101 = 1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::ReadOnlyVariable);
    EXPECT_EQ(run.report.alarm->line, 4u);
    EXPECT_TRUE(run.vacant(1));
    EXPECT_DOUBLE_EQ(run.number(2), 1);
    EXPECT_DOUBLE_EQ(run.number(100), 3);
    EXPECT_TRUE(run.vacant(0));
    EXPECT_TRUE(run.vacant(101));
}

} // namespace
