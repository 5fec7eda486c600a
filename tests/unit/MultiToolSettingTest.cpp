// 多刀固定对刀 on the default machine: O505 (slib-probe.nc) changes to every tool listed in
// #1970-#1989 and sets it on the fixed setter, from mulprobe.nc or the MDI line the Probe page runs.
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

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
    EXPECT_EQ(r.messages.back(), "多刀对刀完成! 3把刀");
    EXPECT_EQ(r.pockets.at(1), 1); // T1 went home first
}

TEST(MultiToolSetting, Flag1993IsOnWhileTheBatchChangesATool) {
    controller::RunSettings settings;
    settings.variables = {{1970, 3}};
    controller::Controller c(bundledMachine(), settings);
    ASSERT_TRUE(c.loadMdi({"M98 P505"}));
    ASSERT_TRUE(c.start());
    bool onInTheChange = false;
    bool offInTheSetting = false;
    bool onInTheSetting = false;
    while (c.advance(0.05) == RunState::Running) {
        const bool flag = c.variable(1993).number == 1.0;
        if (c.variable(1300).number == 3) { // changed: now the setting
            (flag ? onInTheSetting : offInTheSetting) = true;
        } else {
            onInTheChange = onInTheChange || flag;
        }
    }
    EXPECT_EQ(c.runState(), RunState::Finished);
    EXPECT_TRUE(onInTheChange);
    EXPECT_TRUE(offInTheSetting);
    EXPECT_FALSE(onInTheSetting);
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

namespace multi {

controller::RunReport runBatch(controller::Controller& c) {
    EXPECT_TRUE(c.loadMdi({"M98 P505"}));
    return c.run();
}

// Soft limits on with Z stopping at -100: a tool shorter than 20 mm never reaches the setter (top -120).
config::MachineConfig withZFloor(config::MachineConfig cfg) {
    cfg.parameters.set(155, 1);
    for (int n : {161, 162}) {
        cfg.parameters.set(n, -9999);
    }
    for (int n : {166, 167, 168}) {
        cfg.parameters.set(n, 9999);
    }
    cfg.parameters.set(163, -100);
    return cfg;
}

} // namespace multi

TEST(MultiToolSetting, ProgressNamesEachToolAndItsPlace) {
    controller::RunSettings settings;
    settings.variables = {{1970, 5}, {1972, 7}, {1975, 2}};
    controller::Controller c(bundledMachine(), settings);
    controller::RunReport r = multi::runBatch(c);
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    std::vector<std::string> progress;
    for (const std::string& m : r.messages) {
        if (m.rfind("多刀对刀 T", 0) == 0) {
            progress.push_back(m);
        }
    }
    EXPECT_EQ(progress, (std::vector<std::string>{"多刀对刀 T5: 1/3...", "多刀对刀 T7: 2/3...", "多刀对刀 T2: 3/3..."}));
}

TEST(MultiToolSetting, AnAlarmStopsTheBatchKeepingTheToolsSetBeforeIt) {
    // T7 broke: 10 mm long, it would trip the setter at -110, below the Z soft limit of -100
    auto cfg = multi::withZFloor(bundledMachine());
    cfg.toolLengths[6] = 10.0;
    for (int n : {931, 934, 936}) {
        cfg.parameters.set(n, 0);
    }
    controller::RunSettings settings;
    settings.variables = {{1970, 5}, {1971, 7}, {1972, 2}};
    controller::Controller c(cfg, settings);
    controller::RunReport r = multi::runBatch(c);
    ASSERT_EQ(r.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.alarm->code, AlarmCode::SkipNotTriggered);
    EXPECT_NEAR(c.variable(1434).number, tripHeight(cfg, 5), 1e-9); // T5 done
    EXPECT_EQ(c.variable(1436).number, 0.0);                        // T7 not
    EXPECT_EQ(c.variable(1431).number, 0.0);                        // T2 never reached
    EXPECT_EQ(r.tool, 7);
    EXPECT_EQ(c.variable(1993).number, 0.0); // the alarm came in the setting, after the change
    EXPECT_EQ(r.outputs[0], 0);              // the safe state: OUT01 (release) off, the tool clamped
}

TEST(MultiToolSetting, AChangeThatDoesNotHappenStopsTheBatch) {
    // T40 is beyond the magazine and the virtual tools: O20000 leaves T5 in the spindle
    auto cfg = bundledMachine();
    cfg.parameters.set(934, 0);
    controller::RunSettings settings;
    settings.variables = {{1970, 5}, {1971, 40}, {1972, 2}};
    controller::Controller c(cfg, settings);
    controller::RunReport r = multi::runBatch(c);
    ASSERT_EQ(r.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.alarm->message,
              "macro alarm 3008: 多刀对刀停止: 换刀未完成! the change did not happen: see the message before this alarm");
    EXPECT_NEAR(c.variable(1434).number, tripHeight(cfg, 5), 1e-9);
    EXPECT_EQ(r.tool, 5);
    EXPECT_EQ(c.variable(1993).number, 0.0);
}

TEST(MultiToolSetting, WithParam805EachToolIsSetOnceOnly) {
    // the change sets the new tool (param 805); the tool already in the spindle is set by O505
    struct Passes : machine::MachineObserver {
        int first = 0; // G31 passes at the initial speed: one per setting
        void onMachineEvent(const machine::MachineEvent& e) override {
            if (e.type == machine::MachineEvent::Type::Feed && e.to(2) < e.from(2) && e.feed == 250) {
                ++first;
            }
        }
    } passes;
    auto cfg = bundledMachine();
    cfg.parameters.set(805, 1);
    controller::RunSettings settings;
    settings.variables = {{1970, 1}, {1971, 4}};
    settings.observer = &passes;
    controller::Controller c(cfg, settings);
    controller::RunReport r = multi::runBatch(c);
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(passes.first, 2);
    EXPECT_NEAR(c.variable(1430).number, tripHeight(cfg, 1), 1e-9);
    EXPECT_NEAR(c.variable(1433).number, tripHeight(cfg, 4), 1e-9);
}

} // namespace
