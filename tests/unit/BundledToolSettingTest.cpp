// Every bundled M350 machine gets the tool-setting macros (slib-probe.nc) and a fixed setter in its
// world: a change to T2 with param 805 on ends with T2 set on the setter, where the world says it
// trips, and the multi-tool setting sets T1 and T3.
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

const std::vector<std::string> kM350Machines{"m350-linear16", "m350-rack-top",   "m350-follow-row",
                                             "m350-servo-disc", "m350-multi-head", "m350-manual"};

// The variable of tool k's Z offset: params 930+ in the magazine, 973+ for a virtual tool.
int offsetVariable(const config::MachineConfig& cfg, int tool) {
    const int capacity = static_cast<int>(cfg.parameters.get(801));
    return tool <= capacity ? 1430 + tool - 1 : 1473 + tool - capacity - 1;
}

TEST(BundledToolSetting, Param805SetsTheNewToolOnEveryMachine) {
    for (const std::string& name : kM350Machines) {
        auto cfg = bundledMachine(name);
        cfg.parameters.set(805, 1);
        const int offset = offsetVariable(cfg, 2);
        cfg.parameters.set(offset - 500, 0);
        ProgramRun r = runProgram(cfg, lines({"T2", "M30"}));
        EXPECT_RUN_OK(r) << name;
        EXPECT_EQ(r.report.tool, 2) << name;
        EXPECT_NEAR(r.number(offset), tripHeight(cfg, 2), 1e-9) << name;
    }
}

TEST(BundledToolSetting, EverySetToolAgreesWithItsMachinesWorld) {
    // the offsets the machine folders ship for set tools are where their tools trip the setter
    // (but the default machine's T4: params.toml has -57.99, 0.01 mm off its world, a tool to set again)
    for (const std::string& name : kM350Machines) {
        auto cfg = bundledMachine(name);
        for (int tool = 1; tool <= static_cast<int>(cfg.toolLengths.size()); ++tool) {
            double stored = cfg.parameters.get(offsetVariable(cfg, tool) - 500);
            if (stored != 0.0 && !(name == "m350-linear16" && tool == 4)) {
                EXPECT_NEAR(stored, tripHeight(cfg, tool), 1e-9) << name << " T" << tool;
            }
        }
    }
}

TEST(BundledToolSetting, MultiToolSettingOnEveryMachine) {
    for (const std::string& name : kM350Machines) {
        auto cfg = bundledMachine(name);
        for (int tool : {1, 3}) {
            cfg.parameters.set(offsetVariable(cfg, tool) - 500, 0);
        }
        controller::RunSettings settings;
        settings.variables = {{1970, 3}, {1971, 1}};
        controller::Controller c(cfg, settings);
        ASSERT_TRUE(c.loadMdi({"M98 P505"})) << name;
        controller::RunReport r = c.run();
        ASSERT_EQ(r.status, controller::RunStatus::Ok) << name << ": " << (r.alarm ? r.alarm->message : "");
        EXPECT_EQ(r.tool, 1) << name;
        for (int tool : {1, 3}) {
            EXPECT_NEAR(c.variable(offsetVariable(cfg, tool)).number, tripHeight(cfg, tool), 1e-9) << name << " T" << tool;
        }
    }
}

} // namespace
