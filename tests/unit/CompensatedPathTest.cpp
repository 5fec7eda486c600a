// G41/G42 through the interpreter: the machine follows the tool-center path, read from the trace.
#include "RunProgram.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <utility>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

std::vector<std::pair<double, double>> toolPath(const std::string& program) {
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    auto run = runProgram(fanucMachine(), program, settings);
    EXPECT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    std::vector<std::pair<double, double>> points;
    std::istringstream lines(trace.str());
    for (std::string line; std::getline(lines, line);) {
        auto event = nlohmann::json::parse(line);
        if (event["type"] == "move") {
            points.emplace_back(event["to"]["X"].get<double>(), event["to"]["Y"].get<double>());
        }
    }
    return points;
}

TEST(CompensatedPath, G41InsideASquareFollowsTheOffsetCorners) {
    auto points = toolPath(lines({"G10 L11 P1 R2", "G90 G00 X10 Y10", "G41 D1 G01 X10 Y0 F600", "X20", "Y20", "X0",
                                  "Y0", "X10", "G40 X10 Y10", "M30"}));
    const std::vector<std::pair<double, double>> expected = {
        {10, 10}, {12, 2}, {18, 2}, {18, 18}, {2, 18}, {2, 2}, {10, 2}, {10, 10}}; // entry as LinuxCNC's
    ASSERT_EQ(points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(points[i].first, expected[i].first, 1e-9) << "move " << i;
        EXPECT_NEAR(points[i].second, expected[i].second, 1e-9) << "move " << i;
    }
}

TEST(CompensatedPath, PlungeUnderCompensationMovesZWhereTheToolStands) {
    auto run = runFanuc(lines({"G10 L11 P1 R2", "G00 X10 Y10 Z5", "G41 D1 G01 X10 Y0 F600", "Z-1", "#100 = #5021",
                               "#101 = #5022", "#102 = #5023", "X20", "G40 X20 Y10", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    // With a Z move next, the start-up block ends perpendicular to its own end (FANUC type A): the
    // entry ran -Y, so G41 puts the tool at +X of its end point; then Z went down there.
    EXPECT_NEAR(run.number(100), 12, 1e-9);
    EXPECT_NEAR(run.number(101), 0, 1e-9);
    EXPECT_NEAR(run.number(102), -1, 1e-9);
}

TEST(CompensatedPath, GougeIsAnAlarmOnTheLineThatCausesIt) {
    auto run = runFanuc(lines({"G10 L11 P1 R5", "G00 X0 Y-10", "G41 D1 G01 X0 Y0 F600", "X10", "Y1", "X0",
                               "G40 X0 Y-10", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(run.report.alarm->message.find("gouge"), std::string::npos) << run.alarmText();
}

} // namespace

namespace {

TEST(CompensatedPath, G19CompensatesInTheYZPlane) {
    // The square of the G17 test drawn in Y (across) and Z (up), seen from +X: the same offsets.
    auto run = runFanuc(lines({"G10 L11 P1 R2", "G19 G90 G00 Y10 Z10", "G41 D1 G01 Y10 Z0 F600", "Y20", "Z20",
                               "Y0", "#100 = #5022", "#101 = #5023", "G40 Y10 Z10", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    // The machine runs one move behind the program under compensation: after "Y0" it has reached
    // the end of the "Z20" side, the trimmed inside corner Y18 Z18; X never moved.
    EXPECT_NEAR(run.number(100), 18, 1e-9);
    EXPECT_NEAR(run.number(101), 18, 1e-9);
    EXPECT_NEAR(run.report.machine(0), 0, 1e-9);
}

TEST(CompensatedPath, ChangingThePlaneUnderCompensationIsAnAlarm) {
    auto run = runFanuc(lines({"G10 L11 P1 R2", "G00 X10 Y10", "G41 D1 G01 X10 Y0 F600", "G18 X20", "M30"}));
    EXPECT_EQ(run.alarmText(), "invalid_word at " + run.fileName +
                                   ":4:1: the plane changed under cutter compensation: cancel it with G40 first");
}

} // namespace
