// Multi-process heads (多工序, M350 magazine type 1) and the manual change of a machine without a
// magazine: the bundled machines' flows and what a wrong line does.
#include "RunProgram.h"
#include "ShippedMacros.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

constexpr const char* kHeads = "m350-multi-head";

void expectCrash(const ProgramRun& r, const std::string& message) {
    ASSERT_TRUE(r.report.alarm) << "no crash";
    EXPECT_EQ(r.report.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.report.alarm->message, message);
}

TEST(MultiHead, T3RaisesEveryHeadThenLowersHead3) {
    ProgramRun r = runProgram(bundledMachine(kHeads), lines({"T3", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.tool, 3);
    EXPECT_EQ(r.number(1300), 3);
    EXPECT_EQ(r.report.pockets.at(1), 1); // head 1 parked up
    EXPECT_EQ(r.report.pockets.at(3), 0);
    EXPECT_EQ(r.report.outputs[2], 0); // OUT03 head 1 up
    EXPECT_EQ(r.report.outputs[4], 1); // OUT05 head 3 down
    EXPECT_NEAR(r.report.work(2), 58.0, 1e-9); // work Z uses head 3's offset, param 932
}

TEST(MultiHead, T0ParksEveryHead) {
    ProgramRun r = runProgram(bundledMachine(kHeads), lines({"T0", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.tool, 0);
    for (int head = 1; head <= 4; ++head) {
        EXPECT_EQ(r.report.pockets.at(head), head);
    }
}

TEST(MultiHead, SwitchingHeadsWithZDownLowersTheNewHeadIntoTheWork) {
    std::string program = "G53 Z-30\nT2\nM30\n" +
                          withLine(shippedLibrary(kHeads), "G53 Z#1306 F#1312                   //up", "//Z stays");
    ProgramRun r = runProgram(bundledMachine(kHeads), program);
    expectCrash(r, "head 2 came down at X5.000 Y5.000 Z-30.000, below the change height Z0.000 (param 806): it hit "
                   "the work. Raise Z before switching heads");
    ASSERT_TRUE(r.report.alarm);
    EXPECT_EQ(r.report.alarm->file, "slib-m.nc"); // M170's output line
    EXPECT_EQ(r.report.alarm->line, lineOf(shippedLibrary("m350-linear16", "slib-m.nc"),
                                           "#[1552+#1280-1] = #1282"));
}

TEST(MultiHead, LeavingAHeadDownPloughsItThroughTheWorkOnTheNextMove) {
    std::string program = "T2\nG1 X100 F1000\nM30\n" +
                          withLine(shippedLibrary(kHeads), "M169                                //every head up", "");
    ProgramRun r = runProgram(bundledMachine(kHeads), program);
    expectCrash(r, "heads 1, 2 were down together when the carriage moved from X5.000 Y5.000 Z0.000 to X100.000 Y5.000 "
              "Z0.000: the lower one ploughed through the work (close the others first, M169 M171 M173 M175)");
    ASSERT_TRUE(r.report.alarm);
    EXPECT_EQ(r.report.alarm->line, 2u);
    EXPECT_EQ(r.report.tool, 0); // two heads down: no one tool in use
}

TEST(ManualChange, EveryToolIsChangedByHandAtTheManualChangePlace) {
    ProgramRun r = runProgram(bundledMachine("m350-manual"), lines({"T3", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.tool, 3);
    EXPECT_EQ(r.number(1300), 3);
    EXPECT_TRUE(r.report.pockets.empty());
    ASSERT_EQ(r.report.messages.size(), 4u);
    EXPECT_EQ(r.report.messages[0], "请取下虚拟刀[T1]后,按外部启动键!");
    EXPECT_EQ(r.report.messages[2], "请手动更换虚拟刀号[T3]后,按外部启动键进行自动对刀!");
    EXPECT_NEAR(r.report.machine(0), 20.0, 1e-9); // params 816-818
    EXPECT_NEAR(r.report.work(2), 38.0, 1e-9);    // T3's virtual Z offset, param 975
}

TEST(ManualChange, TargetZeroAndToolsBeyondTwentyAreRefused) {
    ProgramRun zero = runProgram(bundledMachine("m350-manual"), lines({"T0", "M30"}));
    EXPECT_RUN_OK(zero);
    EXPECT_EQ(zero.report.tool, 1);
    EXPECT_EQ(zero.report.messages.back(), "目标刀具号不能为0! ");
    ProgramRun beyond = runProgram(bundledMachine("m350-manual"), lines({"T21", "M30"}));
    EXPECT_RUN_OK(beyond);
    EXPECT_EQ(beyond.report.tool, 1);
    EXPECT_LT(beyond.report.simTime, 0.01);
}

} // namespace
