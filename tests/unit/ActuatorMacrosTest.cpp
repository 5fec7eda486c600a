// The default machine's slib-m.nc: M150-M155 drive the outputs of their IO-page functions and
// M300-M306 wait for their sensors, each finding its port in its parameter triple.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace m350;
using namespace m350::test;

// The rack would see a tool released at the home position dropped: these tests work the drawbar
// with an empty spindle.
controller::RunSettings emptySpindle() {
    controller::RunSettings settings;
    settings.tool = 0;
    return settings;
}

TEST(ActuatorMacros, ReleaseAndClampDriveOut01AndWaitForIn11) {
    // OUT01 (param 750) drives the cylinder; IN11 answers 150 ms later (machine.toml io_links)
    ProgramRun r = runProgram(bundledMachine(), lines({"M154", "#100 = #1552", "M301", "#101 = #1530",
                                                       "M155", "#102 = #1552", "M302", "#103 = #1530", "M30"}),
                              emptySpindle());
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 1); // released: OUT01 on
    EXPECT_EQ(r.number(101), 1); // M301 returned once IN11 said released
    EXPECT_EQ(r.number(102), 0);
    EXPECT_EQ(r.number(103), 0);
    EXPECT_NEAR(r.report.simTime, 0.31, 0.02); // two 150 ms strokes, polled every 10 ms
}

TEST(ActuatorMacros, TheActiveLevelComesFromTheTriple) {
    auto cfg = bundledMachine();
    cfg.parameters.set(752, 0); // the release valve is active low
    ProgramRun r = runProgram(cfg, lines({"M154", "#100 = #1552", "M155", "#101 = #1552", "M30"}), emptySpindle());
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 0);
    EXPECT_EQ(r.number(101), 1);
}

TEST(ActuatorMacros, ADisabledFunctionIsSkipped) {
    auto cfg = bundledMachine();
    cfg.parameters.set(751, 0); // release output not enabled
    cfg.parameters.set(624, 0); // released sensor not enabled
    ProgramRun r = runProgram(cfg, lines({"M154", "#100 = #1552", "M301", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 0);
    EXPECT_LT(r.report.simTime, 0.01); // nothing to wait for
}

TEST(ActuatorMacros, EveryActuatorAndWaitUsesItsOwnPorts) {
    auto cfg = bundledMachine();
    // dust cover on OUT05 -> IN09, magazine slide on OUT06 -> IN06 (out) and IN08 (in, active 0)
    for (auto [param, pin, level] : {std::tuple{762, 5, 1}, {753, 6, 1}, {632, 9, 1}, {629, 6, 1}, {697, 8, 0}}) {
        cfg.parameters.set(param, pin);
        cfg.parameters.set(param + 1, 1);
        cfg.parameters.set(param + 2, level);
    }
    cfg.ioLinks.push_back({5, 9, 0.4, false});
    cfg.ioLinks.push_back({6, 6, 1.0, false});
    cfg.ioLinks.push_back({6, 8, 1.0, false}); // magazine-in sensor reads 0 while the slide is in
    ProgramRun r = runProgram(cfg, lines({"M150", "M305", "#100 = #1528", "M152", "M303", "#101 = #1557", "M153",
                                          "M304", "M151", "M306", "#102 = #1528", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 1);
    EXPECT_EQ(r.number(101), 1);
    EXPECT_EQ(r.number(102), 0);
    EXPECT_NEAR(r.report.simTime, 0.4 + 1.0 + 1.0 + 0.4, 0.1);
}

TEST(ActuatorMacros, AStuckSensorEndsInTheWatchdogAlarmInsideTheWait) {
    controller::RunSettings settings = emptySpindle();
    settings.heldInputs[11] = 0;
    ProgramRun r = runProgram(bundledMachine(), lines({"M154", "M301", "M30"}), settings);
    EXPECT_EQ(r.report.alarm->message, "IN11 (tool released) never became 1: waited 10.0 s at slib-m.nc:51");
}

} // namespace

namespace {

TEST(ActuatorMacros, ASlowSensorDelaysTheWaitAndAVerySlowOneTripsTheWatchdog) {
    for (double lateness : {3.0, 12.0}) {
        ProgramRun r = loadProgram(bundledMachine(), lines({"M154", "M301", "M30"}), emptySpindle());
        ASSERT_TRUE(r.loaded);
        r.controller->setInputFault(11, machine::InputFault::delayed(lateness));
        r.report = r.controller->run();
        if (lateness < 10.0) {
            EXPECT_RUN_OK(r);
            EXPECT_NEAR(r.report.simTime, 0.15 + lateness, 0.02);
        } else {
            EXPECT_EQ(r.report.alarm->code, AlarmCode::SensorTimeout) << r.alarmText();
        }
    }
}

} // namespace

namespace {

TEST(ActuatorMacros, AnAlarmDrivesEveryOutputToItsInactiveLevel) {
    auto cfg = bundledMachine();
    cfg.parameters.set(752, 0); // release valve active low: clamped (safe) is 1
    ProgramRun r = runProgram(cfg, lines({"M154", "#1555 = 1", "#3 = 1/0", "M30"}));
    EXPECT_EQ(r.report.alarm->code, AlarmCode::DivisionByZero);
    EXPECT_EQ(r.report.outputs[0], 1); // OUT01 back to clamp
    EXPECT_EQ(r.report.outputs[3], 0); // OUT04, no function: off
}

} // namespace

namespace {

TEST(ActuatorMacros, TheTraceShowsTheSensorAnsweringItsActuator) {
    std::ostringstream trace;
    controller::RunSettings settings = emptySpindle();
    settings.trace = &trace;
    ProgramRun r = runProgram(bundledMachine(), lines({"M154", "M301", "M155", "M302", "M30"}), settings);
    EXPECT_RUN_OK(r);
    std::vector<std::string> io;
    std::istringstream in(trace.str());
    for (std::string line; std::getline(in, line);) {
        if (line.find(R"("type":"io")") != std::string::npos) {
            io.push_back(line);
        }
    }
    ASSERT_EQ(io.size(), 4u) << trace.str();
    // OUT01 from M154 (slib-m.nc:34), then IN11 150 ms later, credited to the same line
    EXPECT_NE(io[0].find(R"("level":1,"line":34,"port":"OUT01","t":0.0003)"), std::string::npos) << io[0];
    EXPECT_NE(io[1].find(R"("level":1,"line":34,"port":"IN11","t":0.1503)"), std::string::npos) << io[1];
    EXPECT_NE(io[2].find(R"("port":"OUT01")"), std::string::npos) << io[2];
    EXPECT_NE(io[3].find(R"("level":0,"line":39,"port":"IN11")"), std::string::npos) << io[3];
}

} // namespace
