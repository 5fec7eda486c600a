// Z 清零 on the workpiece (the manual's 对刀原理): with every tool set on the fixed setter, zeroing
// work Z with one tool touching the work makes G54 Z = B - D, the distance between the setter and
// the work, and then A = B - C - D puts every set tool's tip on the work at work Z 0.
#include "ToolSettingSupport.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

// The default machine's world: the work's surface lies 12.5 mm below the setter's top (-120),
// as the machine Z a zero-length tool's nose would have touching it.
constexpr double kSurface = -120 - 12.5;

double length(const config::MachineConfig& cfg, int tool) { return cfg.toolLengths[static_cast<std::size_t>(tool - 1)]; }

// Runs MDI lines to their end; the machine Z they leave.
double runToEnd(controller::Controller& c, const std::vector<std::string>& lines) {
    EXPECT_TRUE(c.loadMdi(lines));
    controller::RunReport r = c.run();
    EXPECT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    return r.machine(2);
}

TEST(WorkZeroAcrossTools, ZeroingWithOneToolPutsEverySetToolOnTheWork) {
    auto cfg = bundledMachine();
    controller::RunSettings settings;
    settings.variables = {{1970, 1}, {1971, 2}, {1972, 3}, {1973, 4}, {1974, 9}};
    controller::Controller c(cfg, settings);
    runToEnd(c, {"M98 P505"}); // every tool used set on the setter: D = its trip height
    for (int tool : {1, 2, 3, 4, 9}) {
        EXPECT_NEAR(c.parameter(929 + tool), tripHeight(cfg, tool), 1e-9) << "T" << tool;
    }
    // T2 brought down until its tip touches the work, then 清零 (the Coord page's Clear Z)
    runToEnd(c, {"T2", "G53 X300 Y200", "G53 Z" + std::to_string(kSurface + length(cfg, 2))});
    c.zeroWorkAxis(2);
    // C = B - D: the nose's machine Z there less T2's trip height, whatever tool did it
    EXPECT_NEAR(c.variable(807).number, kSurface + length(cfg, 2) - tripHeight(cfg, 2), 1e-6);
    EXPECT_NEAR(c.variable(807).number, kSurface - cfg.setterTop, 1e-6);
    for (int tool : {1, 3, 4, 9, 2}) {
        const double nose = runToEnd(c, {"T" + std::to_string(tool), "G90 G00 Z0"});
        EXPECT_NEAR(nose - length(cfg, tool), kSurface, 1e-6) << "T" << tool;
        // A = B - C - D with A = 0
        EXPECT_NEAR(nose - c.variable(807).number - c.parameter(929 + tool), 0.0, 1e-6);
    }
}

TEST(WorkZeroAcrossTools, ATouchedOffWorkZeroStaysThroughAFirstSetting) {
    // 清零 with T5 never set (D = 0): G54 Z is then the nose's machine Z on the work; the first
    // fixed setting turns it into the setter-to-work distance, and the tip still lands on the work
    auto cfg = bundledMachine();
    cfg.parameters.set(934, 0);
    controller::RunSettings settings;
    settings.tool = 5;
    controller::Controller c(cfg, settings);
    runToEnd(c, {"G53 X300 Y200 Z" + std::to_string(kSurface + length(cfg, 5))});
    c.zeroWorkAxis(2);
    EXPECT_NEAR(c.variable(807).number, kSurface + length(cfg, 5), 1e-6);
    const double nose = runToEnd(c, {"#1502 = 1", "M98 P502", "G53 X300 Y200", "G90 G00 Z0"});
    EXPECT_NEAR(c.variable(807).number, kSurface - cfg.setterTop, 1e-6);
    EXPECT_NEAR(nose - length(cfg, 5), kSurface, 1e-6);
}

} // namespace
