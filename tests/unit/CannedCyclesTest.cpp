// Canned drilling cycles (G73 G74 G81-G84, G80): the exact moves each one makes, read from the trace,
// computed here by hand. The alarms are in CannedCycleAlarmsTest.cpp.
#include "TracedRun.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;
using Events = std::vector<std::string>;

Events fanucEvents(const std::string& program, controller::RunSettings settings = {}) {
    TracedRun traced = runTraced(fanucMachine(), program, std::move(settings));
    EXPECT_RUN_OK(traced.run);
    return traced.events;
}

TEST(CannedCycles, G81FeedsToTheBottomAndRapidsBackToTheInitialLevel) {
    Events expected{"rapid X0 Y0 Z10", "rapid X5 Y6 Z10", "rapid X5 Y6 Z2", "feed X5 Y6 Z-3 F100",
                    "rapid X5 Y6 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G98 G81 X5 Y6 Z-3 R2 F100", "G80", "M30"})), expected);
}

TEST(CannedCycles, G82DwellsAtTheBottomForPMilliseconds) {
    Events expected{"rapid X0 Y0 Z10",     "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",
                    "feed X5 Y0 Z-3 F100", "dwell 0.5",       "rapid X5 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G98 G82 X5 Z-3 R2 P500 F100", "G80", "M30"})),
              expected);
}

TEST(CannedCycles, G83LeavesTheHoleToRAfterEachPeckAndComesBackToDAboveTheDepth) {
    // d defaults to LinuxCNC's 0.254 mm while parameter 224 is 0
    Events expected{"rapid X0 Y0 Z10",     "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",
                    "feed X5 Y0 Z-2 F100", "rapid X5 Y0 Z2",  "rapid X5 Y0 Z-1.746",
                    "feed X5 Y0 Z-6 F100", "rapid X5 Y0 Z2",  "rapid X5 Y0 Z-5.746",
                    "feed X5 Y0 Z-7 F100", "rapid X5 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G98 G83 X5 Z-7 R2 Q4 F100", "G80", "M30"})), expected);
}

TEST(CannedCycles, Parameter224SetsThePeckClearance) {
    controller::RunSettings settings;
    settings.parameters[param::kDrillingRetraction] = 1.0;
    Events expected{"rapid X0 Y0 Z10", "rapid X5 Y0 Z10",     "rapid X5 Y0 Z2",      "feed X5 Y0 Z-2 F100",
                    "rapid X5 Y0 Z2",  "rapid X5 Y0 Z-1",     "feed X5 Y0 Z-6 F100", "rapid X5 Y0 Z2",
                    "rapid X5 Y0 Z-5", "feed X5 Y0 Z-7 F100", "rapid X5 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G98 G83 X5 Z-7 R2 Q4 F100", "G80", "M30"}), settings),
              expected);
}

TEST(CannedCycles, G73BacksOffByDInsideTheHole) {
    Events expected{"rapid X0 Y0 Z10",     "rapid X5 Y0 Z10",     "rapid X5 Y0 Z2",
                    "feed X5 Y0 Z-2 F100", "rapid X5 Y0 Z-1.746", "feed X5 Y0 Z-6 F100",
                    "rapid X5 Y0 Z-5.746", "feed X5 Y0 Z-7 F100", "rapid X5 Y0 Z2"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G99 G73 X5 Z-7 R2 Q4 F100", "G80", "M30"})), expected);
}

TEST(CannedCycles, G84TapsOutAtTheFeedWithTheSpindleReversedThenRapidsToTheInitialLevel) {
    Events expected{"spindle FWD",         "rapid X0 Y0 Z10", "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",
                    "feed X5 Y0 Z-3 F100", "dwell 0.25",      "spindle REV",     "feed X5 Y0 Z2 F100",
                    "spindle FWD",         "rapid X5 Y0 Z10", "spindle STOP"};
    EXPECT_EQ(
        fanucEvents(lines({"M03 S500", "G90 G00 X0 Y0 Z10", "G98 G84 X5 Z-3 R2 P250 F100", "G80", "M30"})),
        expected);
}

TEST(CannedCycles, G74TapsWithTheSpindleDirectionsSwapped) {
    Events expected{"spindle REV",        "rapid X0 Y0 Z10",     "rapid X5 Y0 Z10",
                    "rapid X5 Y0 Z2",     "feed X5 Y0 Z-3 F100", "spindle FWD",
                    "feed X5 Y0 Z2 F100", "spindle REV",         "spindle STOP"};
    EXPECT_EQ(fanucEvents(lines({"M04 S500", "G90 G00 X0 Y0 Z10", "G99 G74 X5 Z-3 R2 F100", "G80", "M30"})),
              expected);
}

TEST(CannedCycles, TheCycleRepeatsAtEveryPositionWithItsDrillingDataKept) {
    Events expected{"rapid X0 Y0 Z10",       "rapid X10 Y10 Z10", "rapid X10 Y10 Z1",
                    "feed X10 Y10 Z-5 F200", "rapid X10 Y10 Z1",  "rapid X20 Y10 Z1",
                    "feed X20 Y10 Z-5 F200", "rapid X20 Y10 Z1",  "rapid X20 Y20 Z1",
                    "feed X20 Y20 Z-5 F200", "rapid X20 Y20 Z1"};
    EXPECT_EQ(
        fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G99 G81 X10 Y10 Z-5 R1 F200", "X20", "Y20", "G80", "M30"})),
        expected);
}

TEST(CannedCycles, G98ReturnsToTheLevelTheCycleBeganAtEvenAfterG99Holes) {
    // The second hole is reached at R, where G99 left the tool, and left to the initial level.
    Events expected{"rapid X0 Y0 Z10", "rapid X10 Y0 Z10", "rapid X10 Y0 Z1",      "feed X10 Y0 Z-5 F200",
                    "rapid X10 Y0 Z1", "rapid X20 Y0 Z1",  "feed X20 Y0 Z-5 F200", "rapid X20 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G99 G81 X10 Z-5 R1 F200", "G98 X20", "G80", "M30"})),
              expected);
}

TEST(CannedCycles, G91TakesRFromTheInitialLevelZFromRAndStepsXYKTimes) {
    Events expected{"rapid X0 Y0 Z10",   "rapid X10 Y5 Z10",  "rapid X10 Y5 Z2",  "feed X10 Y5 Z-4 F200",
                    "rapid X10 Y5 Z10",  "rapid X20 Y10 Z10", "rapid X20 Y10 Z2", "feed X20 Y10 Z-4 F200",
                    "rapid X20 Y10 Z10", "rapid X30 Y15 Z10", "rapid X30 Y15 Z2", "feed X30 Y15 Z-4 F200",
                    "rapid X30 Y15 Z10"};
    EXPECT_EQ(
        fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G91 G98 G81 X10 Y5 Z-6 R-8 K3 F200", "G90 G80", "M30"})),
        expected);
}

TEST(CannedCycles, LRepeatsLikeKAndUnderG90DrillsTheSameHoleAgain) {
    Events expected{"rapid X0 Y0 Z10", "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",      "feed X5 Y0 Z-3 F100",
                    "rapid X5 Y0 Z2",  "rapid X5 Y0 Z2",  "feed X5 Y0 Z-3 F100", "rapid X5 Y0 Z2"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G99 G81 X5 Z-3 R2 L2 F100", "G80", "M30"})), expected);
}

TEST(CannedCycles, K0KeepsTheDrillingDataAndDrillsNothing) {
    Events expected{"rapid X0 Y0 Z10", "rapid X6 Y0 Z10", "rapid X6 Y0 Z2", "feed X6 Y0 Z-3 F100",
                    "rapid X6 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G98 G81 X5 Z-3 R2 K0 F100", "X6", "G80", "M30"})),
              expected);
}

TEST(CannedCycles, ACycleBegunBelowRRisesToRBeforePositioning) {
    Events expected{"rapid X0 Y0 Z0", "rapid X0 Y0 Z2", "rapid X5 Y0 Z2", "feed X5 Y0 Z-3 F100",
                    "rapid X5 Y0 Z2"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z0", "G98 G81 X5 Z-3 R2 F100", "G80", "M30"})), expected);
}

TEST(CannedCycles, ZOrRAloneDrillsAgainWhereTheToolStands) {
    Events expected{"rapid X0 Y0 Z10", "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",      "feed X5 Y0 Z-3 F100",
                    "rapid X5 Y0 Z2",  "rapid X5 Y0 Z2",  "feed X5 Y0 Z-4 F100", "rapid X5 Y0 Z2",
                    "rapid X5 Y0 Z2",  "rapid X5 Y0 Z3",  "feed X5 Y0 Z-4 F100", "rapid X5 Y0 Z3"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y0 Z10", "G99 G81 X5 Z-3 R2 F100", "Z-4", "R3", "G80", "M30"})),
              expected);
}

TEST(CannedCycles, G80EndsTheCycleAndTheMotionModeBeforeItMovesAgain) {
    auto traced =
        runTraced(fanucMachine(), lines({"G90 G01 X0 Y0 Z10 F300", "G98 G81 X5 Z-3 R2 F100", "#100 = #4009",
                                         "G80 X8", "#101 = #4009", "#102 = #4001", "M30"}));
    EXPECT_RUN_OK(traced.run);
    Events expected{"feed X0 Y0 Z10 F300", "rapid X5 Y0 Z10", "rapid X5 Y0 Z2",
                    "feed X5 Y0 Z-3 F100", "rapid X5 Y0 Z10", "feed X8 Y0 Z10 F100"};
    EXPECT_EQ(traced.events, expected);
    EXPECT_EQ(traced.run.number(100), 81);
    EXPECT_EQ(traced.run.number(101), 80);
    EXPECT_EQ(traced.run.number(102), 1);
}

TEST(CannedCycles, AMotionCodeCancelsTheCycle) {
    auto traced = runTraced(fanucMachine(), lines({"G90 G00 X0 Y0 Z10", "G98 G81 X5 Z-3 R2 F100", "G00 X8",
                                                   "X9", "#100 = #4009", "M30"}));
    EXPECT_RUN_OK(traced.run);
    Events expected{"rapid X0 Y0 Z10", "rapid X5 Y0 Z10", "rapid X5 Y0 Z2", "feed X5 Y0 Z-3 F100",
                    "rapid X5 Y0 Z10", "rapid X8 Y0 Z10", "rapid X9 Y0 Z10"};
    EXPECT_EQ(traced.events, expected);
    EXPECT_EQ(traced.run.number(100), 80);
}

TEST(CannedCycles, G18DrillsAlongYWithZXPositioning) {
    Events expected{"rapid X0 Y10 Z0", "rapid X5 Y10 Z3", "rapid X5 Y2 Z3", "feed X5 Y-3 Z3 F100",
                    "rapid X5 Y10 Z3"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X0 Y10 Z0", "G18 G98 G81 X5 Z3 Y-3 R2 F100", "G80 G17", "M30"})),
              expected);
}

TEST(CannedCycles, G19DrillsAlongXWithYZPositioning) {
    Events expected{"rapid X10 Y0 Z0", "rapid X10 Y5 Z7", "rapid X2 Y5 Z7", "feed X-3 Y5 Z7 F100",
                    "rapid X2 Y5 Z7"};
    EXPECT_EQ(fanucEvents(lines({"G90 G00 X10 Y0 Z0", "G19 G99 G81 Y5 Z7 X-3 R2 F100", "G80 G17", "M30"})),
              expected);
}

TEST(CannedCycles, InchesScaleRZAndQ) {
    // R 0.1 in = 2.54 mm, Z -0.1 in, Q 0.05 in = 1.27 mm; d stays 0.254 mm
    Events expected{"rapid X0 Y0 Z10",           "rapid X25.4 Y0 Z10",        "rapid X25.4 Y0 Z2.54",
                    "feed X25.4 Y0 Z1.27 F254",  "rapid X25.4 Y0 Z1.524",     "feed X25.4 Y0 Z0 F254",
                    "rapid X25.4 Y0 Z0.254",     "feed X25.4 Y0 Z-1.27 F254", "rapid X25.4 Y0 Z-1.016",
                    "feed X25.4 Y0 Z-2.54 F254", "rapid X25.4 Y0 Z10"};
    EXPECT_EQ(fanucEvents(lines(
                  {"G21 G90 G00 X0 Y0 Z10", "G20", "G98 G73 X1 Z-0.1 R0.1 Q0.05 F10", "G80 G21", "M30"})),
              expected);
}

TEST(CannedCycles, TheM350RunsTheCyclesTooWithItsOwnParameter224) {
    auto config = m350Machine();
    config.parameters.set(param::kDrillingRetraction, 0.5);
    auto traced =
        runTraced(std::move(config), lines({"G90 G00 X0 Y0 Z10", "G99 G73 X5 Z-5 R1 Q3 F100", "G80", "M30"}));
    EXPECT_RUN_OK(traced.run);
    Events expected{"rapid X0 Y0 Z10",   "rapid X5 Y0 Z10",     "rapid X5 Y0 Z1", "feed X5 Y0 Z-2 F100",
                    "rapid X5 Y0 Z-1.5", "feed X5 Y0 Z-5 F100", "rapid X5 Y0 Z1"};
    EXPECT_EQ(traced.events, expected);
}

} // namespace
