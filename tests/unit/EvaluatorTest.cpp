// Expression semantics of both dialects, observed through whole programs: operators, comparisons,
// functions, indirect references and FANUC's <vacant> rules.
#include "RunProgram.h"

#include <gtest/gtest.h>

using m350::AlarmCode;
using m350::controller::RunStatus;
using m350::test::lines;
using m350::test::loadProgram;
using m350::test::runFanuc;
using m350::test::runM350;

namespace {

constexpr double kEps = 1e-9;

// ---------------------------------------------------------------- M350 dialect

TEST(EvaluatorM350, ArithmeticPrecedenceAndBrackets) {
    auto run = runM350(lines({
        "#1 = 2 + 3 * 4",
        "#2 = [2 + 3] * 4",
        "#3 = 10 - 4 - 3",
        "#4 = 12 / 4 / 3",
        "#5 = -#1 + 1",
        "#6 = 7 / 2",
        "#7 = -[2 - 5]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 14);
    EXPECT_DOUBLE_EQ(run.number(2), 20);
    EXPECT_DOUBLE_EQ(run.number(3), 3);
    EXPECT_DOUBLE_EQ(run.number(4), 1);
    EXPECT_DOUBLE_EQ(run.number(5), -13);
    EXPECT_DOUBLE_EQ(run.number(6), 3.5);
    EXPECT_DOUBLE_EQ(run.number(7), 3);
}

TEST(EvaluatorM350, UnsetVariablesReadZeroNeverVacant) {
    auto run = runM350(lines({"#60 = #45 + 1", "#61 = [#45 == 0]", "#62 = #300", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 1);
    EXPECT_DOUBLE_EQ(run.number(61), 1);
    EXPECT_FALSE(run.vacant(62));
    EXPECT_DOUBLE_EQ(run.number(62), 0);
    EXPECT_FALSE(run.vacant(45));
}

TEST(EvaluatorM350, CStyleComparisonsGiveOneOrZero) {
    auto run = runM350(lines({
        "#1 = [3 > 2]",  "#2 = [2 > 3]",   "#3 = [2 < 3]",  "#4 = [3 < 2]",
        "#5 = [2 >= 2]", "#6 = [1 >= 2]",  "#7 = [2 <= 2]", "#8 = [3 <= 2]",
        "#9 = [4 == 4]", "#10 = [4 == 5]", "#11 = [4 != 5]", "#12 = [4 != 4]",
        "#13 = [1 + 1 == 2]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    const double expected[] = {1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
    for (int i = 0; i < 13; ++i) {
        EXPECT_DOUBLE_EQ(run.number(i + 1), expected[i]) << "#" << i + 1;
    }
}

TEST(EvaluatorM350, KeywordComparisonsAreAcceptedToo) {
    // The factory macros write `WHILE [#[1520+#13-1] NE 0] DO1`.
    auto run = runM350(lines({"#1 = [3 NE 0]", "#2 = [3 EQ 3]", "#3 = [1 GT 2]", "#4 = [1 LE 2]", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 1);
    EXPECT_DOUBLE_EQ(run.number(2), 1);
    EXPECT_DOUBLE_EQ(run.number(3), 0);
    EXPECT_DOUBLE_EQ(run.number(4), 1);
}

TEST(EvaluatorM350, ProductOfConditionsActsAsAnd) {
    auto run = runM350(lines({
        "#1 = 1",
        "#2 = 0",
        "IF [#1 > 0]*[#2 > 0] THEN #10 = 1",
        "IF [#1 > 0]*[#2 == 0] THEN #11 = 1",
        "IF [#1 == 0]*[#2 == 0] THEN #12 = 1",
        "IF [#1 == 0]*[#2 > 0] THEN #13 = 1",
        "#14 = [#1 > 0]*[#2 == 0]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(10), 0);
    EXPECT_DOUBLE_EQ(run.number(11), 1);
    EXPECT_DOUBLE_EQ(run.number(12), 0);
    EXPECT_DOUBLE_EQ(run.number(13), 0);
    EXPECT_DOUBLE_EQ(run.number(14), 1);
}

TEST(EvaluatorM350, TrigonometryInDegrees) {
    auto run = runM350(lines({
        "#1 = SIN[30]", "#2 = COS[60]", "#3 = TAN[45]", "#4 = SIN[-90]", "#5 = COS[180]",
        "#6 = ATAN[1,1]", "#7 = ATAN[1,-1]", "#8 = ATAN[0,1]", "#9 = ATAN[1,0]", "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(1), 0.5, kEps);
    EXPECT_NEAR(run.number(2), 0.5, kEps);
    EXPECT_NEAR(run.number(3), 1.0, kEps);
    EXPECT_NEAR(run.number(4), -1.0, kEps);
    EXPECT_NEAR(run.number(5), -1.0, kEps);
    EXPECT_NEAR(run.number(6), 45.0, kEps);
    EXPECT_NEAR(run.number(7), 135.0, kEps);
    EXPECT_NEAR(run.number(8), 0.0, kEps);
    EXPECT_NEAR(run.number(9), 90.0, kEps);
}

TEST(EvaluatorM350, AbsSqrtAndRounding) {
    auto run = runM350(lines({
        "#1 = ABS[-2.5]", "#2 = ABS[3]", "#3 = SQRT[16]", "#4 = SQRT[2]",
        "#10 = FUP[1.2]", "#11 = FUP[-1.2]", "#12 = FUP[3]",
        "#13 = FIX[1.7]", "#14 = FIX[-1.7]", "#15 = FIX[-2]",
        "#16 = ROUND[2.5]", "#17 = ROUND[-2.5]", "#18 = ROUND[1.4]", "#19 = ROUND[-1.6]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 2.5);
    EXPECT_DOUBLE_EQ(run.number(2), 3);
    EXPECT_DOUBLE_EQ(run.number(3), 4);
    EXPECT_NEAR(run.number(4), 1.41421356237, 1e-9);
    EXPECT_DOUBLE_EQ(run.number(10), 2);   // FUP: away from zero
    EXPECT_DOUBLE_EQ(run.number(11), -2);
    EXPECT_DOUBLE_EQ(run.number(12), 3);
    EXPECT_DOUBLE_EQ(run.number(13), 1);   // FIX: toward zero
    EXPECT_DOUBLE_EQ(run.number(14), -1);
    EXPECT_DOUBLE_EQ(run.number(15), -2);
    EXPECT_DOUBLE_EQ(run.number(16), 3);   // ROUND: half away from zero
    EXPECT_DOUBLE_EQ(run.number(17), -3);
    EXPECT_DOUBLE_EQ(run.number(18), 1);
    EXPECT_DOUBLE_EQ(run.number(19), -2);
}

TEST(EvaluatorM350, IndirectReferences) {
    auto run = runM350(lines({
        "#1 = 60",
        "#[#1] = 7",          // #60 = 7
        "#[#1 + 1] = 8",      // #61 = 8
        "#2 = ##1",           // #60
        "#3 = #[#1 + 1] * 2", // #61 * 2
        "#4 = #[1300]",       // parameter 800
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 7);
    EXPECT_DOUBLE_EQ(run.number(61), 8);
    EXPECT_DOUBLE_EQ(run.number(2), 7);
    EXPECT_DOUBLE_EQ(run.number(3), 16);
    EXPECT_DOUBLE_EQ(run.number(4), 0);
}

TEST(EvaluatorM350, FractionalVariableNumberIsAnAlarm) {
    auto run = runM350(lines({"#1 = 1.5", "#60 = 4", "#[#1] = 2", "#61 = 1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::UndefinedVariable);
    EXPECT_EQ(run.report.alarm->line, 3u);
    EXPECT_DOUBLE_EQ(run.number(60), 4);
    EXPECT_DOUBLE_EQ(run.number(61), 0);
}

TEST(EvaluatorM350, FanucOnlySyntaxIsRejected) {
    for (const char* line : {"#1 = 3 AND 1", "#1 = 7 MOD 2", "#1 = ASIN[0.5]", "#1 = LN[2]", "#1 = ATAN[1]/[1]"}) {
        auto run = loadProgram(m350::test::m350Machine(), lines({line, "M30"}));
        EXPECT_FALSE(run.loaded) << line << " should not load in the m350 dialect";
    }
}

// ---------------------------------------------------------------- FANUC dialect

TEST(EvaluatorFanuc, PlainCopyKeepsVacantArithmeticMakesZero) {
    auto run = runFanuc(lines({
        "#2 = #1",      // vacant copied as vacant
        "#3 = #1 + 5",  // vacant is 0 in arithmetic
        "#4 = #1 * 2",
        "#5 = #0",
        "#6 = #1 - #1",
        "#100 = #33",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_TRUE(run.vacant(1));
    EXPECT_TRUE(run.vacant(2));
    EXPECT_FALSE(run.vacant(3));
    EXPECT_DOUBLE_EQ(run.number(3), 5);
    EXPECT_FALSE(run.vacant(4));
    EXPECT_DOUBLE_EQ(run.number(4), 0);
    EXPECT_TRUE(run.vacant(5));
    EXPECT_FALSE(run.vacant(6));
    EXPECT_TRUE(run.vacant(100));
    EXPECT_TRUE(run.vacant(150)); // never written
}

TEST(EvaluatorFanuc, EqAndNeTellVacantFromZero) {
    auto run = runFanuc(lines({
        "#10 = [#1 EQ #0]", // #1 vacant: true
        "#11 = [#1 EQ 0]",  // vacant is not 0 for EQ
        "#12 = [#1 NE 0]",
        "#13 = [#1 NE #0]",
        "#2 = 0",
        "#14 = [#2 EQ #0]", // 0 is not vacant
        "#15 = [#2 EQ 0]",
        "#16 = [#2 NE #0]",
        "IF [#1 EQ #0] THEN #17 = 1",
        "IF [#2 EQ #0] THEN #18 = 1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(10), 1);
    EXPECT_DOUBLE_EQ(run.number(11), 0);
    EXPECT_DOUBLE_EQ(run.number(12), 1);
    EXPECT_DOUBLE_EQ(run.number(13), 0);
    EXPECT_DOUBLE_EQ(run.number(14), 0);
    EXPECT_DOUBLE_EQ(run.number(15), 1);
    EXPECT_DOUBLE_EQ(run.number(16), 1);
    EXPECT_DOUBLE_EQ(run.number(17), 1);
    EXPECT_TRUE(run.vacant(18));
}

TEST(EvaluatorFanuc, OrderingComparisonsTreatVacantAsZero) {
    auto run = runFanuc(lines({
        "#10 = [#1 GE 0]", "#11 = [#1 GT 0]", "#12 = [#1 LE 0]", "#13 = [#1 LT 0]",
        "#14 = [#1 GT -1]", "#15 = [#1 LT 1]", "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(10), 1);
    EXPECT_DOUBLE_EQ(run.number(11), 0);
    EXPECT_DOUBLE_EQ(run.number(12), 1);
    EXPECT_DOUBLE_EQ(run.number(13), 0);
    EXPECT_DOUBLE_EQ(run.number(14), 1);
    EXPECT_DOUBLE_EQ(run.number(15), 1);
}

TEST(EvaluatorFanuc, BitwiseOperatorsAndMod) {
    auto run = runFanuc(lines({
        "#1 = 12 AND 10", "#2 = 12 OR 3", "#3 = 12 XOR 10", "#4 = 17 MOD 5", "#5 = 20 MOD 4",
        "#6 = 1 + 12 AND 10", // AND binds like *: 1 + 8
        "#7 = [1 EQ 1] AND [2 EQ 2]",
        "#8 = [1 EQ 1] AND [2 EQ 3]",
        "#9 = [1 EQ 2] OR [2 EQ 2]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 8);
    EXPECT_DOUBLE_EQ(run.number(2), 15);
    EXPECT_DOUBLE_EQ(run.number(3), 6);
    EXPECT_DOUBLE_EQ(run.number(4), 2);
    EXPECT_DOUBLE_EQ(run.number(5), 0);
    EXPECT_DOUBLE_EQ(run.number(6), 9);
    EXPECT_DOUBLE_EQ(run.number(7), 1);
    EXPECT_DOUBLE_EQ(run.number(8), 0);
    EXPECT_DOUBLE_EQ(run.number(9), 1);
}

TEST(EvaluatorFanuc, AtanSlashAnswersZeroTo360) {
    auto run = runFanuc(lines({
        "#1 = ATAN[1]/[1]", "#2 = ATAN[1]/[-1]", "#3 = ATAN[-1]/[-1]", "#4 = ATAN[-1]/[1]",
        "#5 = ATAN[0]/[1]", "#6 = ATAN[-1]/[0]", "#7 = ATAN[0]/[-1]", "#8 = ATAN[1]/[1] * 2", "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(1), 45, kEps);
    EXPECT_NEAR(run.number(2), 135, kEps);
    EXPECT_NEAR(run.number(3), 225, kEps);
    EXPECT_NEAR(run.number(4), 315, kEps);
    EXPECT_NEAR(run.number(5), 0, kEps);
    EXPECT_NEAR(run.number(6), 270, kEps);
    EXPECT_NEAR(run.number(7), 180, kEps);
    EXPECT_NEAR(run.number(8), 90, kEps); // the /[b] belongs to ATAN, the * 2 applies to its result
}

TEST(EvaluatorFanuc, ExtendedFunctions) {
    auto run = runFanuc(lines({
        "#1 = ASIN[0.5]", "#2 = ACOS[0.5]", "#3 = LN[1]", "#4 = EXP[0]", "#5 = LN[EXP[2]]",
        "#6 = BIN[37]",   // BCD 0x25 -> 25
        "#7 = BCD[25]",   // 25 -> 0x25 = 37
        "#8 = BCD[1234]", // 0x1234 = 4660
        "#9 = BIN[4660]",
        "#10 = ROUND[-2.5]", "#11 = FIX[-2.7]", "#12 = FUP[-2.2]", "#13 = SQRT[81]", "#14 = ABS[-4]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(1), 30, kEps);
    EXPECT_NEAR(run.number(2), 60, kEps);
    EXPECT_NEAR(run.number(3), 0, kEps);
    EXPECT_NEAR(run.number(4), 1, kEps);
    EXPECT_NEAR(run.number(5), 2, kEps);
    EXPECT_DOUBLE_EQ(run.number(6), 25);
    EXPECT_DOUBLE_EQ(run.number(7), 37);
    EXPECT_DOUBLE_EQ(run.number(8), 4660);
    EXPECT_DOUBLE_EQ(run.number(9), 1234);
    EXPECT_DOUBLE_EQ(run.number(10), -3);
    EXPECT_DOUBLE_EQ(run.number(11), -2);
    EXPECT_DOUBLE_EQ(run.number(12), -3);
    EXPECT_DOUBLE_EQ(run.number(13), 9);
    EXPECT_DOUBLE_EQ(run.number(14), 4);
}

TEST(EvaluatorFanuc, DomainErrorsAreInvalidArgumentAlarms) {
    for (const char* expr : {"ACOS[2]", "ASIN[-1.5]", "LN[0]", "SQRT[-4]"}) {
        auto run = runFanuc(lines({"#100 = 1", std::string("#101 = ") + expr, "#102 = 1", "M30"}));
        EXPECT_EQ(run.report.status, RunStatus::Alarm) << expr;
        ASSERT_TRUE(run.report.alarm) << expr;
        EXPECT_EQ(run.report.alarm->code, AlarmCode::InvalidArgument) << expr;
        EXPECT_EQ(run.report.alarm->line, 2u) << expr;
        EXPECT_DOUBLE_EQ(run.number(100), 1) << expr;
        EXPECT_TRUE(run.vacant(102)) << expr;
    }
}

TEST(EvaluatorFanuc, ModByZeroIsDivisionByZero) {
    auto run = runFanuc(lines({"#1 = 0", "#2 = 5 MOD #1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::DivisionByZero);
    EXPECT_EQ(run.report.alarm->line, 2u);
}

TEST(EvaluatorFanuc, SpacesInsideKeywordsAreInsignificant) {
    auto run = runFanuc(lines({
        "#1 = 1",
        "IF [#1 EQ 1] GO TO 20",
        "#2 = 99",
        "N20 #3 = A B S[-6]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_TRUE(run.vacant(2));
    EXPECT_DOUBLE_EQ(run.number(3), 6);
}

TEST(EvaluatorFanuc, CStyleComparisonsAreRejected) {
    for (const char* line : {"#1 = [1 == 1]", "IF [#1 != 0] GOTO 5", "#1 = [2 > 1]"}) {
        auto run = loadProgram(m350::test::fanucMachine(), lines({line, "N5 M30"}));
        EXPECT_FALSE(run.loaded) << line << " should not load in the fanuc dialect";
    }
}

} // namespace

namespace m350::test {

// Issue 13: a chain of 150,000 operators on one line crashed the evaluator (one stack frame each).
TEST(EvaluatorChain, AVeryLongOperatorChainIsEvaluatedWithoutDeepRecursion) {
    std::string line = "#1=1";
    for (int i = 0; i < 150000; ++i) {
        line += "+1";
    }
    auto run = runM350(line + "\nM30\n");
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(1), 150001.0);
}

} // namespace m350::test
