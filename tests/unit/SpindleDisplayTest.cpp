// The spindle as the panel shows it (STOP FWD REV JOG TAP ORIENT) and the default speed, param 85.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace m350;
using namespace m350::test;
using machine::SpindleState;

config::MachineConfig spindleMachine() {
    auto cfg = m350Machine();
    cfg.parameters.set(85, 12000); // default rpm
    cfg.parameters.set(82, 24000);
    return cfg;
}

TEST(SpindleDisplay, M3WithoutSRunsAtTheDefaultSpeed) {
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    settings.parameters[85] = 9000; // --param 85=9000 counts too
    controller::Controller c(spindleMachine(), settings);
    ASSERT_TRUE(c.loadMdi({"M03"}));
    c.run();
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Forward);
    EXPECT_NE(trace.str().find(R"("rpm":9000.0,"state":"FWD")"), std::string::npos) << trace.str();
}

TEST(SpindleDisplay, TapWhileATappingCycleTurnsTheSpindle) {
    controller::Controller c(spindleMachine(), controller::RunSettings{});
    ASSERT_TRUE(c.loadMdi({"G90 G00 X0 Y0 Z10", "M03 S500", "G99 G84 X5 Y5 Z-6 R2 F500", "G80", "M05"}));
    ASSERT_TRUE(c.start());
    bool sawTap = false;
    for (int step = 0; step < 400 && c.runState() == controller::Controller::RunState::Running; ++step) {
        c.advance(0.05);
        sawTap |= c.status().spindleDisplay() == SpindleState::Tap;
    }
    EXPECT_TRUE(sawTap);
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Stop);
}

TEST(SpindleDisplay, TheJogKeyTurnsTheSpindleOnlyWhileNoProgramRuns) {
    controller::Controller c(spindleMachine(), controller::RunSettings{});
    EXPECT_TRUE(c.manual().spindleJog(true));
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Jog);
    EXPECT_TRUE(c.manual().spindleJog(false));
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Stop);
    ASSERT_TRUE(c.loadMdi({"G04 P5000"}));
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    EXPECT_FALSE(c.manual().spindleJog(true));
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Stop);
}

TEST(SpindleDisplay, OrientShowsOrient) {
    controller::Controller c(spindleMachine(), controller::RunSettings{});
    ASSERT_TRUE(c.loadMdi({"M19"}));
    c.run();
    EXPECT_EQ(c.status().spindleDisplay(), SpindleState::Orient);
}

} // namespace
