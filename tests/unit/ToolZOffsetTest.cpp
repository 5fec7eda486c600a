// The M350's tool Z offsets (manual 1.1.3): work = machine - (G54..G59) - tool Z offset, A = B - C - D,
// kept through every tool change with no G43, with the manual's setter numbers.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

constexpr double kSetterZ = -53.677; // the manual's fixed setter Z (param 137)

config::MachineConfig manualMachine() {
    auto cfg = bundledMachine();
    cfg.parameters.set(930, kSetterZ + 0.0);   // T1 touched the setter here
    cfg.parameters.set(931, kSetterZ + 12.4);  // T2 is 12.4 mm shorter
    cfg.parameters.set(932, kSetterZ - 7.25);  // T3 is 7.25 mm longer
    return cfg;
}

// A = B - C - D for Z, read through the macro variables a program sees.
void expectWorkZ(const ProgramRun& run, int tool, int variableOfWorkZ, int variableOfMachineZ) {
    double b = run.number(variableOfMachineZ);
    double c = run.number(807); // G54 Z
    double d = run.number(1430 + tool - 1);
    EXPECT_NEAR(run.number(variableOfWorkZ), b - c - d, 1e-9) << "tool " << tool;
}

TEST(ToolZOffset, WorkZFollowsEachToolAfterEveryChangeWithoutG43) {
    auto run = runProgram(manualMachine(), lines({"T1", "G53 Z-20", "#100 = #852", "#101 = #882",
                                                  "T2", "G53 Z-20", "#102 = #852", "#103 = #882",
                                                  "T3", "G53 Z-20", "#104 = #852", "#105 = #882", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    expectWorkZ(run, 1, 100, 101);
    expectWorkZ(run, 2, 102, 103);
    expectWorkZ(run, 3, 104, 105);
    // the same machine Z reads 12.4 lower in work Z with the shorter T2, 7.25 higher with T3
    EXPECT_NEAR(run.number(102) - run.number(100), -12.4, 1e-9);
    EXPECT_NEAR(run.number(104) - run.number(100), 7.25, 1e-9);
}

TEST(ToolZOffset, ZeroingZOnTheWorkpieceStoresTheSetterToWorkDistance) {
    controller::RunSettings settings;
    auto cfg = manualMachine();
    controller::Controller c(cfg, settings);
    std::string first = writeTempFile(lines({"G53 Z-70.5", "M30"})); // T1's tip touches the workpiece
    ASSERT_TRUE(c.loadFile(first));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    c.zeroWorkAxis(2);
    // G54 Z = machine Z - T1's offset: the workpiece lies 16.823 below the setter's trigger height
    EXPECT_NEAR(c.variable(807).number, -70.5 - kSetterZ, 1e-9);
    EXPECT_NEAR(c.variable(852).number, 0.0, 1e-9);
}

TEST(ToolZOffset, EverySetToolCutsAtTheSameWorkZeroAfterZeroing) {
    auto cfg = manualMachine();
    cfg.offsets[1][2] = -70.5 - kSetterZ; // as zeroing with T1 left it
    // each tool touches the workpiece top where its own length puts it
    auto run = runProgram(cfg, lines({"T2", "G53 Z[-70.5+12.4]", "#100 = #852", "T3", "G53 Z[-70.5-7.25]",
                                      "#101 = #852", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_NEAR(run.number(100), 0.0, 1e-9);
    EXPECT_NEAR(run.number(101), 0.0, 1e-9);
}

} // namespace
