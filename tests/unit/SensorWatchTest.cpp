// The sensor-wait watchdog: a macro waiting for an input that never comes is reported while it
// waits and stopped with an alarm naming the input, the level it waited for and the line.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

// IN05 is the tool-clamped sensor (param 626: pin 5, enabled, active 1) on this machine.
config::MachineConfig machine() {
    auto cfg = m350Machine();
    cfg.parameters.set(626, 5);
    cfg.parameters.set(627, 1);
    cfg.parameters.set(628, 1);
    return cfg;
}

const std::string kWaitForClamp = lines({"#1 = 0", "WHILE [#1524 NE 1] DO1", "G04 P100", "END1", "M30"});

TEST(SensorWatch, AnInputThatNeverComesEndsInAnAlarmNamingIt) {
    ProgramRun r = runProgram(machine(), kWaitForClamp);
    EXPECT_EQ(r.alarmText(), "sensor_timeout at " + r.fileName + ":2:1: IN05 (tool clamped) never became 1: waited 10.0 s at " +
                                 r.fileName + ":2");
    EXPECT_NEAR(r.report.simTime, 10.0, 0.2); // the watchdog, not the 3600 s run limit
}

TEST(SensorWatch, TheTimeoutIsASetting) {
    controller::RunSettings settings;
    settings.sensorTimeout = 2.5;
    ProgramRun r = runProgram(machine(), kWaitForClamp, settings);
    EXPECT_NE(r.alarmText().find("waited 2.5 s"), std::string::npos) << r.alarmText();
    EXPECT_NEAR(r.report.simTime, 2.5, 0.2);
}

TEST(SensorWatch, TheStatusSaysWhatTheMacroWaitsForAndForHowLong) {
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    controller::Controller c(machine(), settings);
    std::string path = writeTempFile(kWaitForClamp);
    ASSERT_TRUE(c.loadFile(path));
    ASSERT_TRUE(c.start());
    EXPECT_EQ(c.advance(4.0), RunState::Running);
    auto wait = c.operatorPanel().sensorWait();
    ASSERT_TRUE(wait.has_value());
    EXPECT_EQ(wait->input, "IN05 (tool clamped)");
    EXPECT_EQ(wait->awaitedLevel, 1);
    EXPECT_NEAR(wait->seconds, 4.0, 0.2);
    EXPECT_EQ(wait->line, 2u);
    EXPECT_NE(trace.str().find(R"("level":1,"line":2,"port":"IN05","t":)"), std::string::npos) << trace.str();
    EXPECT_NE(trace.str().find(R"("type":"wait")"), std::string::npos);
}

TEST(SensorWatch, ASensorThatComesInTimeIsNoFault) {
    controller::RunSettings settings;
    settings.sensorTimeout = 1.0;
    // OUT02 drives IN05 0.6 s later, as a clamp cylinder would
    auto cfg = machine();
    cfg.ioLinks.push_back({2, 5, 0.6, false});
    ProgramRun r = runProgram(cfg, lines({"#1553 = 1", "WHILE [#1524 NE 1] DO1", "G04 P100", "END1", "M30"}), settings);
    EXPECT_EQ(r.report.status, controller::RunStatus::Ok) << r.alarmText();
}

TEST(SensorWatch, WaitingForTheOperatorIsNoFault) {
    // extern START (param 599) on IN05: a prompt may wait as long as the operator needs
    auto cfg = m350Machine();
    cfg.parameters.set(599, 5);
    cfg.parameters.set(600, 1);
    cfg.parameters.set(601, 1);
    controller::Controller c(cfg, controller::RunSettings{});
    ASSERT_TRUE(c.loadFile(writeTempFile(kWaitForClamp)));
    ASSERT_TRUE(c.start());
    EXPECT_EQ(c.advance(60.0), controller::Controller::RunState::Running); // still waiting, no alarm
    EXPECT_FALSE(c.operatorPanel().sensorWait().has_value());
}

TEST(SensorWatch, ARunWithoutAnOperatorPressesStartWhenAMacroWaitsForIt) {
    auto cfg = m350Machine();
    cfg.parameters.set(599, 5);
    cfg.parameters.set(600, 1);
    cfg.parameters.set(601, 1);
    ProgramRun r = runProgram(cfg, lines({"WHILE [#1524 NE 1] DO1", "G04 P10", "END1", "WHILE [#1524 EQ 1] DO2",
                                          "G04 P10", "END2", "M30"}));
    EXPECT_RUN_OK(r);
    ASSERT_EQ(r.report.messages.size(), 1u);
    EXPECT_EQ(r.report.messages[0], "外部启动 extern START (IN05) pressed at " + r.fileName + ":1 (run without an operator)");
    EXPECT_NEAR(r.report.simTime, 0.01 + 0.3, 0.03); // pressed after the first poll, let go 0.3 s later
}

} // namespace
