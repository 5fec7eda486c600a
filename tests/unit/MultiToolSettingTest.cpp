// 多刀固定对刀 on the default machine: O505 changes to every tool listed in #1970-#1989 and sets it
// on the fixed setter, from the MDI line the Probe page runs.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

double tripHeight(const config::MachineConfig& cfg, int tool) {
    return cfg.setterTop + cfg.toolLengths[static_cast<std::size_t>(tool - 1)];
}

TEST(MultiToolSetting, TheListVariablesAreStored) {
    ProgramRun r = runProgram(bundledMachine(), lines({"#1970 = 4", "#1989 = 9", "#1993 = 1", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(1970), 4);
    EXPECT_EQ(r.number(1989), 9);
    EXPECT_EQ(r.number(1993), 1);
}

TEST(MultiToolSetting, EveryListedToolIsSetAndTheOthersAreLeft) {
    auto cfg = bundledMachine();
    for (int n : {931, 934, 936}) {
        cfg.parameters.set(n, 0); // T2, T5, T7 not set
    }
    const double t3 = cfg.parameters.get(932);
    controller::RunSettings settings;
    settings.variables = {{1970, 5}, {1971, 0}, {1972, 7}, {1975, 2}};
    controller::Controller c(cfg, settings);
    ASSERT_TRUE(c.loadMdi({"M98 P505"}));
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_NEAR(c.variable(1434).number, tripHeight(cfg, 5), 1e-9);
    EXPECT_NEAR(c.variable(1436).number, tripHeight(cfg, 7), 1e-9);
    EXPECT_NEAR(c.variable(1431).number, tripHeight(cfg, 2), 1e-9);
    EXPECT_EQ(c.variable(1435).number, 0.0); // T6 not listed
    EXPECT_EQ(c.variable(1432).number, t3);  // T3 not listed
    EXPECT_EQ(r.tool, 2);                    // the last listed tool stays in the spindle
    EXPECT_EQ(c.variable(1993).number, 0.0);
    EXPECT_EQ(r.messages.back(), "多刀对刀完成!");
    EXPECT_EQ(r.pockets.at(1), 1); // T1 went home first
}

TEST(MultiToolSetting, Flag1993IsOnWhileTheBatchRuns) {
    controller::RunSettings settings;
    settings.variables = {{1970, 3}};
    controller::Controller c(bundledMachine(), settings);
    ASSERT_TRUE(c.loadMdi({"M98 P505"}));
    ASSERT_TRUE(c.start());
    EXPECT_EQ(c.advance(5.0), RunState::Running);
    EXPECT_EQ(c.variable(1993).number, 1.0);
    EXPECT_EQ(c.advance(600.0), RunState::Finished);
    EXPECT_EQ(c.variable(1993).number, 0.0);
    EXPECT_NEAR(c.variable(1432).number, tripHeight(bundledMachine(), 3), 1e-9);
}

TEST(MultiToolSetting, AnEmptyListChangesNothing) {
    controller::Controller c(bundledMachine(), {});
    ASSERT_TRUE(c.loadMdi({"M98 P505"}));
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Ok);
    EXPECT_EQ(r.tool, 1);
    EXPECT_NEAR(r.machine(2), 0.0, 1e-9);
}

} // namespace
