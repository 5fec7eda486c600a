// Lines that parse but are never what the author meant (the M350 manual's damaged
// `G53 X[#1330+#1300-1]`) stop the run with an alarm when reached, before the machine moves.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;

TEST(SuspectLine, DamagedPocketLineRaisesAnAlarmInsteadOfMoving) {
    auto run = test::runM350(test::lines({"#1300 = 2", "G53 X0", "G53 X[#1330+#1300-1] F1000", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SuspectLine);
    EXPECT_EQ(run.report.alarm->line, 3u);
    EXPECT_NE(run.report.alarm->message.find("did you mean X#[1330+#1300-1]?"), std::string::npos)
        << run.report.alarm->message;
    EXPECT_DOUBLE_EQ(run.report.machine(0), 0.0); // X stayed where line 2 put it
}

TEST(SuspectLine, UnreachedSuspectLineDoesNotStopTheRun) {
    auto run = test::runM350(test::lines({"GOTO9", "G53 X[#1330+#1300-1]", "N9 M30"}));
    EXPECT_EQ(run.report.status, controller::RunStatus::Ok);
}

TEST(M99InMain, M350EndsTheProgram) {
    auto run = test::runM350(test::lines({"#100 = #100 + 1", "M99"}));
    EXPECT_EQ(run.report.status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(run.controller->variable(100).number, 1.0);
}

TEST(M99InMain, FanucRestartsTheProgramUntilM30) {
    auto run = test::runFanuc(test::lines({"#100 = #100 + 1", "IF [#100 GE 3] GOTO 9", "M99", "N9 M30"}));
    EXPECT_EQ(run.report.status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(run.controller->variable(100).number, 3.0);
}

} // namespace

namespace {

TEST(DwellBlock, FanucG04XIsATimeNotAMove) {
    auto run = m350::test::runFanuc(m350::test::lines({"G90 G00 X10", "G04 X2", "#100 = #5021", "M30"}));
    EXPECT_EQ(run.report.status, m350::controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(run.controller->variable(100).number, 10.0);
}

} // namespace
