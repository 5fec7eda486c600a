// Virtual tools (虚拟刀, param 803): T17-T36 on the default machine are changed by hand at the
// manual change place (params 816-818), after a prompt, when the extern START key is pressed.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(VirtualTool, TheRackToolGoesHomeThenTheOperatorPutsTheVirtualOneIn) {
    ProgramRun r = runProgram(bundledMachine(), lines({"T17", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(1300), 17);
    EXPECT_EQ(r.report.tool, 17);
    EXPECT_EQ(r.report.pockets.at(1), 1); // T1 back in its fork
    ASSERT_GE(r.report.messages.size(), 2u);
    EXPECT_EQ(r.report.messages[0], "请手动更换虚拟刀号[T17]后,按外部启动键进行自动对刀!");
    EXPECT_NE(r.report.messages[1].find("外部启动 extern START (IN05) pressed"), std::string::npos);
    EXPECT_NEAR(r.report.machine(0), 300, 1e-9); // at the manual change place
    EXPECT_NEAR(r.report.machine(1), 300, 1e-9);
    // work Z uses the virtual tool's offset, param 973 (#1473): 0 - (-12.5) - (-40.25)
    EXPECT_NEAR(r.report.work(2), 52.75, 1e-9);
}

TEST(VirtualTool, BackFromAVirtualToolToARackTool) {
    ProgramRun r = runProgram(bundledMachine(), lines({"T17", "T2", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.tool, 2);
    EXPECT_EQ(r.report.pockets.at(2), 0);
    EXPECT_EQ(r.report.pockets.at(1), 1);
    EXPECT_EQ(r.report.messages[2], "请取下虚拟刀[T17]后,按外部启动键!");
}

TEST(VirtualTool, WithoutTheStartKeyNothingChanges) {
    auto cfg = bundledMachine();
    cfg.parameters.set(600, 0); // extern START not enabled
    ProgramRun r = runProgram(cfg, lines({"T17", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(1300), 0); // T1 went home; no tool came
    EXPECT_EQ(r.report.tool, 0);
    EXPECT_EQ(r.report.messages.back(), "外部启动键未设置! extern START, params 599-601, is not set");
}

TEST(VirtualTool, BeyondTheVirtualToolsOrWithThemOffNothingHappens) {
    for (auto [virtualOn, target] : {std::pair{1, 37}, {0, 17}}) {
        auto cfg = bundledMachine();
        cfg.parameters.set(803, virtualOn);
        ProgramRun r = runProgram(cfg, lines({"T" + std::to_string(target), "M30"}));
        EXPECT_RUN_OK(r);
        EXPECT_EQ(r.report.tool, 1) << target;
        EXPECT_LT(r.report.simTime, 0.01);
    }
}

} // namespace
