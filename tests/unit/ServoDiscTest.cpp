// The servo disc magazine (圆盘刀库, M350 type 4): the device alone, then the bundled machine's own
// O20000 through every flow, the crashes a wrong line causes, and a disc that never says it is in
// position.
#include "core/devices/ServoDisc.h"

#include "RunProgram.h"
#include "ShippedMacros.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using devices::ServoDisc;
using Eigen::Vector3d;

constexpr const char* kDisc = "m350-servo-disc";

// Eight pockets; T1 in the spindle, pocket 1 (empty) at the station X100 Y0, cups at Z-80.
ServoDisc disc() {
    ServoDisc::Geometry g;
    g.station = Vector3d(100, 0, -80);
    g.pockets = 8;
    g.secondsPerPocket = 0.5;
    g.settleSeconds = 0.1;
    return ServoDisc(g, {0, 2, 3, 4, 5, 6, 7, 8}, 1, 1);
}

TEST(ServoDiscDevice, TurnsTheShortestWayAndCarriesTheToolsRound) {
    ServoDisc d = disc();
    ServoDisc::Turn t = d.turnTo(7, 0.0, {100, 0, 0}); // 1 -> 7: two pockets backwards
    EXPECT_FALSE(t.crash);
    EXPECT_DOUBLE_EQ(t.seconds, 2 * 0.5 + 0.1);
    EXPECT_EQ(d.pocketAtStation(), 7);
    EXPECT_TRUE(d.turning(1.0));
    EXPECT_FALSE(d.turning(1.2));
    EXPECT_EQ(d.pocketTool(7), 7);
    EXPECT_EQ(d.pocketTool(1), 0);
    EXPECT_DOUBLE_EQ(d.turnTo(7, 2.0, {100, 0, 0}).seconds, 0.0); // already there
}

TEST(ServoDiscDevice, PutsAToolInItsCupAndTakesTheNextFromAnother) {
    ServoDisc d = disc();
    EXPECT_FALSE(d.move({100, 0, 0}, {100, 0, -80}, false, false, 0.0)); // T1 down into cup 1
    EXPECT_FALSE(d.drawbar(true, {100, 0, -80}));
    EXPECT_EQ(d.pocketTool(1), 1);
    EXPECT_FALSE(d.move({100, 0, -80}, {100, 0, 0}, false, false, 1.0));
    EXPECT_FALSE(d.turnTo(4, 2.0, {100, 0, 0}).crash);
    EXPECT_FALSE(d.move({100, 0, 0}, {100, 0, -80}, false, false, 5.0)); // released, onto T4
    EXPECT_FALSE(d.drawbar(false, {100, 0, -80}));
    EXPECT_EQ(d.spindleTool(), 4);
    EXPECT_EQ(d.pocketTool(4), 0);
    EXPECT_EQ(d.pocketTool(1), 1);
}

TEST(ServoDiscDevice, TurningWithTheSpindleInsideIsACrash) {
    ServoDisc d = disc();
    EXPECT_FALSE(d.move({100, 0, 0}, {100, 0, -80}, false, false, 0.0));
    ServoDisc::Turn t = d.turnTo(3, 1.0, {100, 0, -80});
    ASSERT_TRUE(t.crash);
    EXPECT_EQ(*t.crash, "the disc turned from pocket 1 to pocket 3 while T1 in the spindle was inside it at "
                        "X100.000 Y0.000 Z-80.000: raise Z to the change height (param 806) before turning the disc");
}

TEST(ServoDiscDevice, ComingDownWhileItTurnsIsACrash) {
    ServoDisc d = disc();
    ASSERT_FALSE(d.turnTo(3, 0.0, {100, 0, 0}).crash); // 1.1 s
    auto crash = d.move({100, 0, 0}, {100, 0, -80}, false, false, 0.5);
    ASSERT_TRUE(crash);
    EXPECT_EQ(*crash, "came down into the disc at X100.000 Y0.000 Z-80.000 while it was still turning to pocket 3: "
                      "wait for its in-position signal first");
}

TEST(ServoDiscDevice, APocketItDoesNotHaveIsAPositionFault) {
    ServoDisc d = disc();
    auto t = d.turnTo(9, 0.0, {100, 0, 0});
    ASSERT_TRUE(t.crash);
    EXPECT_EQ(*t.crash, "the disc was told to turn to pocket 9, but it has pockets 1-8: its drive stops with a "
                        "position fault");
}

// What the bundled machine does with MDI lines, one controller for all of them.
controller::RunReport mdi(controller::Controller& c, const std::string& line) {
    EXPECT_TRUE(c.loadMdi({line}));
    return c.run();
}

TEST(ServoDiscMachine, T1ToT3ReturnsT1ToItsCupAndFetchesT3) {
    controller::Controller c(bundledMachine(kDisc), {});
    controller::RunReport r = mdi(c, "T3");
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 3);
    EXPECT_EQ(c.variable(1300).number, 3);
    EXPECT_EQ(r.pockets.at(1), 1);
    EXPECT_EQ(r.pockets.at(3), 0);
    EXPECT_EQ(r.machine(2), 0.0); // Z up at param 806
    EXPECT_EQ(r.machine(0), 650.0);
    // in position again, and the drive was told pocket 3 = 0b0011 on OUT05-OUT08
    EXPECT_EQ(c.variable(1520 + 13 - 1).number, 1);
    EXPECT_EQ(r.outputs[4], 1);
    EXPECT_EQ(r.outputs[5], 1);
    EXPECT_EQ(r.outputs[6], 0);
    RecordProperty("change_sim_s", std::to_string(r.simTime));
    EXPECT_GT(r.simTime, 5.0);
    EXPECT_LT(r.simTime, 30.0);
}

TEST(ServoDiscMachine, T0PutsTheToolAwayAndAFetchFillsTheEmptySpindle) {
    controller::Controller c(bundledMachine(kDisc), {});
    controller::RunReport r = mdi(c, "T0");
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 0);
    EXPECT_EQ(c.variable(1300).number, 0);
    EXPECT_EQ(r.pockets.at(1), 1);
    r = mdi(c, "T7");
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 7);
    EXPECT_EQ(r.pockets.at(7), 0);
    EXPECT_EQ(r.pockets.at(1), 1);
}

TEST(ServoDiscMachine, SameToolAndOutOfRangeChangeNothing) {
    controller::Controller c(bundledMachine(kDisc), {});
    for (const char* line : {"T1", "T11"}) {
        controller::RunReport r = mdi(c, line);
        ASSERT_EQ(r.status, controller::RunStatus::Ok) << line;
        EXPECT_EQ(r.tool, 1) << line;
        EXPECT_LT(r.simTime, 0.1) << line; // no motion at all
    }
}

// [magazine] station is where the iron stands: param 807 entered 10 mm too deep then drives the tool
// being put away into its cup, where without it the station would follow the parameter.
TEST(ServoDiscMachine, AStationKeptWhereItStandsCrashesAWrongCupHeight) {
    config::MachineConfig config = bundledMachine(kDisc);
    config.parameters.set(807, -95);
    controller::Controller followed(config, {});
    EXPECT_EQ(mdi(followed, "T3").status, controller::RunStatus::Ok);
    config.magazine.station = std::array<double, 3>{650, 20, -85};
    controller::Controller c(config, {});
    controller::RunReport r = mdi(c, "T3");
    ASSERT_TRUE(r.alarm) << "no crash";
    EXPECT_EQ(r.alarm->code, AlarmCode::Crash);
    config.parameters.set(807, -85);
    controller::Controller right(config, {});
    r = mdi(right, "T3");
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 3);
}

// The machine's slib-g.nc with one line made wrong, carried by the program file after "T3".
ProgramRun changeWith(const std::string& right, const std::string& wrong, controller::RunSettings settings = {}) {
    std::string program = "T3\nM30\n" + withLine(shippedLibrary(kDisc), right, wrong);
    return runProgram(bundledMachine(kDisc), program, std::move(settings));
}

TEST(ServoDiscMachine, TurningBeforeZIsUpIsReportedOnTheStartLine) {
    const std::string up = "G53 Z#1306 F#1312                   //up, the tool stays in its cup\n";
    ProgramRun r = changeWith(up, "");
    ASSERT_TRUE(r.report.alarm) << "no crash";
    EXPECT_EQ(r.report.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.report.alarm->message,
              "the disc turned from pocket 1 to pocket 3 while the spindle nose over T1 was inside it at X650.000 "
              "Y20.000 Z-85.000: raise Z to the change height (param 806) before turning the disc");
    const std::string program = "T3\nM30\n" + withLine(shippedLibrary(kDisc), up, "");
    EXPECT_EQ(r.report.alarm->line, lineOf(program, "#[1552+#12-1] = 1                   //start"));
}

TEST(ServoDiscMachine, NotWaitingForInPositionComesDownIntoATurningDisc) {
    ProgramRun r = changeWith("WHILE [#[1520+#13-1] NE 1] DO2      //wait until the disc stands in position\n"
                              "G04 P10\nEND2\n",
                              "");
    ASSERT_TRUE(r.report.alarm) << "no crash";
    EXPECT_EQ(r.report.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.report.alarm->message, "came down into the disc at X650.000 Y20.000 Z-85.000 while it was still "
                                       "turning to pocket 3: wait for its in-position signal first");
}

TEST(ServoDiscMachine, AnInPositionSignalThatNeverComesStopsTheRunNamingIt) {
    controller::RunSettings settings;
    settings.sensorTimeout = 2.0;
    controller::Controller c(bundledMachine(kDisc), settings);
    c.setInputFault(13, machine::InputFault::stuck(0));
    controller::RunReport r = mdi(c, "T3");
    ASSERT_TRUE(r.alarm);
    EXPECT_EQ(r.alarm->code, AlarmCode::SensorTimeout);
    const std::uint32_t wait =
        lineOf(shippedLibrary(kDisc), "WHILE [#[1520+#13-1] NE 1] DO2      //wait until the disc stands in position");
    EXPECT_EQ(r.alarm->message,
              "IN13 (disc in position) never became 1: waited 2.0 s at slib-g.nc:" + std::to_string(wait));
    EXPECT_EQ(r.outputs[0], 0); // the drawbar back at its safe level: clamped
}

TEST(ServoDiscMachine, ASlowInPositionSensorLetsTheMacroGoOnWhileTheDiscStillTurns) {
    // the sensor reports every change 0.8 s late: right after the start pulse it still says "in
    // position" from before, and the spindle comes down into the turning disc
    controller::Controller c(bundledMachine(kDisc), {});
    c.setInputFault(13, machine::InputFault::delayed(0.8));
    controller::RunReport r = mdi(c, "T3");
    ASSERT_TRUE(r.alarm);
    EXPECT_EQ(r.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.alarm->message, "came down into the disc at X650.000 Y20.000 Z-85.000 while it was still turning "
                                "to pocket 3: wait for its in-position signal first");
    EXPECT_EQ(r.alarm->line, lineOf(shippedLibrary(kDisc), "G53 Z#1307 F#1313                   //onto the tool"));
}

TEST(ServoDiscMachine, ABouncingInPositionSensorIsWaitedOut) {
    controller::Controller c(bundledMachine(kDisc), {});
    c.setInputFault(13, machine::InputFault::bouncing(0.05));
    controller::RunReport r = mdi(c, "T3");
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 3);
}

} // namespace
