// Stops the program asks for: M00, M01 (only with the optional stop on) and the M350's G04 P-1.
// The run holds after the block's motion until START (resume()); run() presses START by itself.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;

const std::string kProgram = lines({"G01 X10 F600", "M00", "G01 X20", "M01", "G01 X30", "G04 P-1", "G01 X40", "M30"});

std::unique_ptr<controller::Controller> started(config::MachineConfig cfg, const std::string& program,
                                                std::string& fileName, controller::RunSettings settings = {}) {
    auto c = std::make_unique<controller::Controller>(std::move(cfg), std::move(settings));
    std::string path = writeTempFile(program);
    fileName = std::filesystem::path(path).filename().string();
    EXPECT_TRUE(c->loadFile(path));
    EXPECT_TRUE(c->start());
    return c;
}

TEST(OperatorStop, M00HoldsUntilStartAndM01IsSkippedWhileItsSwitchIsOff) {
    std::string file;
    auto c = started(m350Machine(), kProgram, file);
    EXPECT_EQ(c->advance(100.0), RunState::Hold);
    EXPECT_EQ(c->programStop(), "M00 program stop (" + file + ":2)");
    EXPECT_NEAR(c->status().report().machine(0), 10.0, 1e-9); // the move before it is complete
    EXPECT_EQ(c->advance(50.0), RunState::Hold);       // waits as long as nobody presses START
    EXPECT_NEAR(c->status().report().machine(0), 10.0, 1e-9);

    c->resume(); // START
    EXPECT_TRUE(c->programStop().empty());
    EXPECT_EQ(c->advance(100.0), RunState::Hold); // M01 passed by (#1500 = 0): stopped at G04 P-1
    EXPECT_EQ(c->programStop(), "G04 P-1 waits for START (" + file + ":6)");
    EXPECT_NEAR(c->status().report().machine(0), 30.0, 1e-9);

    c->resume();
    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    EXPECT_NEAR(c->status().report().machine(0), 40.0, 1e-9);
}

TEST(OperatorStop, M01StopsWhenTheOptionalStopIsOn) {
    for (bool bySetting : {true, false}) {
        std::string file;
        controller::RunSettings settings;
        settings.optionalStop = bySetting;
        if (!bySetting) {
            settings.variables[1500] = 1; // the M350's M1 使能
        }
        auto c = started(m350Machine(), kProgram, file, settings);
        c->advance(100.0);
        c->resume();
        EXPECT_EQ(c->advance(100.0), RunState::Hold) << bySetting;
        EXPECT_EQ(c->programStop(), "M01 optional stop (" + file + ":4)") << bySetting;
        EXPECT_NEAR(c->status().report().machine(0), 20.0, 1e-9);
    }
}

TEST(OperatorStop, RunPressesStartItselfAndSaysSo) {
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    ProgramRun r = runM350(kProgram, settings);
    EXPECT_EQ(r.report.status, controller::RunStatus::Ok) << r.alarmText();
    EXPECT_NEAR(r.report.machine(0), 40.0, 1e-9);
    ASSERT_EQ(r.report.messages.size(), 2u);
    EXPECT_EQ(r.report.messages[0], "M00 program stop (" + r.fileName + ":2): START pressed (run without an operator)");
    EXPECT_EQ(r.report.messages[1],
              "G04 P-1 waits for START (" + r.fileName + ":6): START pressed (run without an operator)");
    const std::string t = trace.str();
    EXPECT_NE(t.find(R"("reason":"M00 program stop","t":)"), std::string::npos) << t;
    EXPECT_NE(t.find(R"("line":2,"reason":"M00 program stop")"), std::string::npos) << t;
    EXPECT_NE(t.find(R"("type":"resume")"), std::string::npos) << t;
}

TEST(OperatorStop, ResetClearsAStop) {
    std::string file;
    auto c = started(m350Machine(), kProgram, file);
    c->advance(100.0);
    c->reset();
    EXPECT_EQ(c->runState(), RunState::Idle);
    EXPECT_TRUE(c->programStop().empty());
}

TEST(OperatorStop, NegativeDwellIsRefusedExceptTheM350sWaitForStart) {
    ProgramRun fanuc = runFanuc(lines({"G04 P-1", "M30"}));
    EXPECT_EQ(fanuc.alarmText(), "invalid_word at " + fanuc.fileName + ":1:5: P-1: a dwell cannot be negative");
    ProgramRun m350 = runM350(lines({"G04 P-2", "M30"}));
    EXPECT_EQ(m350.alarmText(),
              "invalid_word at " + m350.fileName + ":1:5: P-2: a dwell cannot be negative (G04 P-1 waits for START)");
}

} // namespace
