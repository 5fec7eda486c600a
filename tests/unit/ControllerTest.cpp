// The controller façade: machine-side variables (positions, offsets, tool, IO), virtual time, run
// settings, MDI, and how alarms are reported in both dialects.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using m350::AlarmCode;
using m350::alarmKey;
using m350::controller::Controller;
using m350::controller::RunReport;
using m350::controller::RunSettings;
using m350::controller::RunStatus;
using m350::test::bundledMachine;
using m350::test::fanucMachine;
using m350::test::lines;
using m350::test::loadProgram;
using m350::test::m350Machine;
using m350::test::runFanuc;
using m350::test::runM350;
using m350::test::runProgram;

namespace {

constexpr double kEps = 1e-9;

// ---------------------------------------------------------------- M350 machine variables

TEST(ControllerM350, BundledMachineParametersAndOffsetsAsVariables) {
    auto run = runProgram(bundledMachine(), lines({"#60 = #805", "#61 = #806", "#62 = #807", "#63 = #1300",
                                                   "#64 = #1301", "#65 = #629", "#66 = #578", "#67 = #1431", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 300);
    EXPECT_DOUBLE_EQ(run.number(61), 200);
    EXPECT_DOUBLE_EQ(run.number(62), -12.5);
    EXPECT_DOUBLE_EQ(run.number(63), 1);  // param 800: current tool
    EXPECT_DOUBLE_EQ(run.number(64), 16); // param 801: magazine capacity
    EXPECT_DOUBLE_EQ(run.number(65), 10); // param 129: floating setter thickness
    EXPECT_DOUBLE_EQ(run.number(66), 1);  // param 78: G54
    EXPECT_DOUBLE_EQ(run.number(67), -48.12);
}

TEST(ControllerM350, WorkZSubtractsG54AndTheCurrentToolsOffset) {
    auto run = runProgram(bundledMachine(), lines({"#1300 = 2", "G53 X0 Y0 Z0", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.report.tool, 1); // the spindle still holds T1: #1300 is what the controller believes
    EXPECT_DOUBLE_EQ(run.controller->config().parameters.get(800), 2); // #1300 is param 800
    EXPECT_NEAR(run.report.machine(2), 0, kEps);
    EXPECT_NEAR(run.report.work(0), -300, kEps);
    EXPECT_NEAR(run.report.work(1), -200, kEps);
    EXPECT_NEAR(run.report.work(2), 60.62, 1e-9); // 0 - (-12.5) - (-48.12)
    EXPECT_NEAR(run.number(852), 60.62, 1e-9);   // work Z in G54
}

TEST(ControllerM350, G54MoveAndMachinePositionVariables) {
    auto run = runProgram(bundledMachine(), lines({"G90 G54 G00 X10 Y20 Z5", "#60 = #880", "#61 = #881", "#62 = #882",
                                                   "#63 = #850", "#64 = #852", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(60), 310, kEps);
    EXPECT_NEAR(run.number(61), 220, kEps);
    EXPECT_NEAR(run.number(62), 5 - 12.5 - 53.677, 1e-9); // T1's Z offset is param 930
    EXPECT_NEAR(run.number(63), 10, 1e-9);
    EXPECT_NEAR(run.number(64), 5, 1e-9);
    EXPECT_NEAR(run.report.machine(0), 310, kEps);
    EXPECT_NEAR(run.report.work(2), 5, 1e-9);
}

TEST(ControllerM350, WritingOffsetAndToolVariablesChangesWorkCoordinates) {
    auto run = runProgram(bundledMachine(), lines({"#807 = 0", "#805 = 100", "#1430 = -50", "G53 X0 Z0", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.report.work(0), -100, kEps);
    EXPECT_NEAR(run.report.work(2), 50, kEps); // 0 - 0 - (-50)
    EXPECT_DOUBLE_EQ(run.controller->config().parameters.get(930), -50);
}

TEST(ControllerM350, InputsAreReadOnly) {
    auto run = runM350(lines({"#100 = 1", "#1520 = 1", "#101 = 1", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::ReadOnlyVariable);
    EXPECT_EQ(run.report.alarm->file, run.fileName);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_NE(run.report.alarm->message.find("#1520"), std::string::npos) << run.report.alarm->message;
    EXPECT_DOUBLE_EQ(run.number(100), 1);
    EXPECT_DOUBLE_EQ(run.number(101), 0);
}

TEST(ControllerM350, OutputsAreOneBased) {
    auto run = runM350(lines({"#1552 = 1", "#1553 = 1", "#1553 = 0", "#1572 = 1", "#1556 = 0.5", "#60 = #1552",
                              "#61 = #1553", "#62 = #[1552 + 3 - 1]", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.report.outputs[0], 1);  // OUT01
    EXPECT_EQ(run.report.outputs[1], 0);  // OUT02
    EXPECT_EQ(run.report.outputs[4], 1);  // OUT05: any non-zero value switches it on
    EXPECT_EQ(run.report.outputs[20], 1); // OUT21
    EXPECT_EQ(run.report.outputs[2], 0);
    EXPECT_DOUBLE_EQ(run.number(60), 1);
    EXPECT_DOUBLE_EQ(run.number(61), 0);
    EXPECT_DOUBLE_EQ(run.number(62), 0);
}

TEST(ControllerM350, LinkedInputAnswersAfterItsDelay) {
    // bundled wiring: OUT01 drives IN11 (#1530) 150 ms later (an empty spindle: no tool to drop)
    m350::controller::RunSettings settings;
    settings.tool = 0;
    auto run = runProgram(bundledMachine(), lines({"#1552 = 1", "#60 = #1530", "G04 P200", "#61 = #1530", "#1552 = 0",
                                                   "G04 P200", "#62 = #1530", "M30"}), settings);
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 0);
    EXPECT_DOUBLE_EQ(run.number(61), 1);
    EXPECT_DOUBLE_EQ(run.number(62), 0);
}

TEST(ControllerM350, HeldInputsComeFromTheSettings) {
    RunSettings settings;
    settings.heldInputs[7] = 1;
    auto run = runM350(lines({"#60 = #1526", "#61 = #1527", "M30"}), settings);
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 1);
    EXPECT_DOUBLE_EQ(run.number(61), 0);
}

TEST(ControllerM350, DwellAdvancesSimulatedTime) {
    auto without = runM350(lines({"#1 = 1", "M30"}));
    auto with = runM350(lines({"G04 P1500", "M30"}));
    auto twice = runM350(lines({"G04 P1500", "G04 P250", "M30"}));
    EXPECT_RUN_OK(with);
    EXPECT_LT(without.report.simTime, 0.01);
    EXPECT_NEAR(with.report.simTime - without.report.simTime, 1.5, 1e-6);
    EXPECT_NEAR(twice.report.simTime - with.report.simTime, 0.25, 1e-3);
}

TEST(ControllerM350, RunawayLoopHitsTheSimulatedTimeLimit) {
    RunSettings settings;
    settings.maxSimTime = 1;
    auto run = runM350(lines({"#100 = 5", "WHILE [1] DO1", "#101 = #101 + 1", "END1", "M30"}), settings);
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SimulatedTimeLimit) << run.alarmText();
    EXPECT_EQ(run.report.alarm->file, run.fileName);
    EXPECT_GE(run.report.alarm->line, 2u);
    EXPECT_LE(run.report.alarm->line, 4u);
    EXPECT_GE(run.report.simTime, 1.0);
    EXPECT_LT(run.report.simTime, 1.1);
    EXPECT_DOUBLE_EQ(run.number(100), 5);
    EXPECT_GT(run.number(101), 100);
}

TEST(ControllerM350, AlarmSwitchesOutputsOff) {
    auto run = runM350(lines({"#1552 = 1", "#1 = 1 / 0", "M30"}));
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    EXPECT_EQ(run.report.outputs[0], 0);
}

// The bundled O20000 changes the tool through the rack; T3 ends with tool 3 in the spindle.
TEST(ControllerM350, BundledToolChangeRuns) {
    auto run = runProgram(bundledMachine(), lines({"T3", "G53 Z0", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.report.tool, 3);
    EXPECT_DOUBLE_EQ(run.number(1300), 3);
    EXPECT_DOUBLE_EQ(run.number(1504), 3);
    EXPECT_EQ(run.report.outputs[0], 0); // clamped again
    EXPECT_NEAR(run.report.machine(0), 170, kEps); // above T3's pocket
    EXPECT_NEAR(run.report.machine(1), 60, kEps);  // the pre-point
    EXPECT_NEAR(run.report.work(2), 0 + 12.5 + 61.305, 1e-9);
    EXPECT_GE(run.report.simTime, 0.4); // two G04 P200
    EXPECT_TRUE(run.report.messages.empty());
    ASSERT_EQ(run.report.pockets.size(), 16u);
    EXPECT_EQ(run.report.pockets.at(3), 0);
    EXPECT_EQ(run.report.pockets.at(1), 1);
}

TEST(ControllerM350, BundledToolChangeRefusesWhenNotHomed) {
    RunSettings settings;
    settings.homed = false;
    auto run = runProgram(bundledMachine(), lines({"#60 = #1515 + #1516 + #1517", "T3", "M30"}), settings);
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 0);
    EXPECT_EQ(run.report.tool, 1);
    ASSERT_EQ(run.report.messages.size(), 1u);
    EXPECT_NE(run.report.messages[0].find("归零"), std::string::npos) << run.report.messages[0];
}

// G handlers O9000+n come from the G library, M handlers O10000+n from the M library; the
// program's own O number wins over both.
TEST(ControllerM350, HandlersComeFromTheirLibraries) {
    auto config = m350Machine();
    std::string gLibrary = m350::test::writeTempFile(
        lines({"O9100", "#60 = #0", "#61 = #1", "M99", "O9101", "#63 = 1", "M99", "O10101", "#64 = 1", "M99"}));
    std::string mLibrary = m350::test::writeTempFile(lines({"O10100", "#62 = #1", "M99"}));
    config.libraries = {{gLibrary, m350::gcode::FileRole::GLibrary}, {mLibrary, m350::gcode::FileRole::MLibrary}};
    auto withLibraries = config;

    auto run = runProgram(config, lines({"G100 X3 Y4", "M100 X5", "G101", "M30", "O9101", "#65 = 1", "M99"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 3);
    EXPECT_DOUBLE_EQ(run.number(61), 4);
    EXPECT_DOUBLE_EQ(run.number(62), 5);
    EXPECT_DOUBLE_EQ(run.number(63), 0); // the program's own O9101 ran instead
    EXPECT_DOUBLE_EQ(run.number(65), 1);

    // O10101 sits in the G library, so M101 has no handler: an unknown M code
    auto wrongLibrary = runProgram(withLibraries, lines({"#100 = 1", "M101", "M30"}));
    EXPECT_EQ(wrongLibrary.report.status, RunStatus::Alarm);
    ASSERT_TRUE(wrongLibrary.report.alarm);
    EXPECT_EQ(wrongLibrary.report.alarm->code, AlarmCode::InvalidWord) << wrongLibrary.alarmText();
    EXPECT_EQ(wrongLibrary.report.alarm->line, 2u);
    EXPECT_DOUBLE_EQ(wrongLibrary.number(64), 0);
    std::remove(gLibrary.c_str());
    std::remove(mLibrary.c_str());
}

// An alarm inside a library names the library file and its line.
TEST(ControllerM350, AlarmInTheLibraryNamesTheLibraryLine) {
    RunSettings settings;
    settings.heldInputs[7] = 1; // the spindle never reports stopped
    settings.maxSimTime = 2;
    auto config = bundledMachine();
    std::string library = config.libraries.empty() ? std::string() : config.libraries.front().path;
    auto run = runProgram(std::move(config), lines({"#100 = 1", "T3", "M30"}), settings);
    EXPECT_EQ(run.report.status, RunStatus::Alarm);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SimulatedTimeLimit);
    EXPECT_EQ(run.report.alarm->file, "slib-g.nc");
    std::ifstream in(library);
    std::string text;
    for (std::uint32_t n = 0; n < run.report.alarm->line && std::getline(in, text); ++n) {
    }
    EXPECT_TRUE(text.find("DO1") != std::string::npos || text.find("G04 P10") != std::string::npos ||
                text.find("END1") != std::string::npos)
        << "line " << run.report.alarm->line << ": " << text;
    EXPECT_EQ(run.report.tool, 1);
    EXPECT_DOUBLE_EQ(run.number(100), 1);
    EXPECT_DOUBLE_EQ(run.number(1504), 3);
}

TEST(ControllerM350, SettingsOverrideParametersVariablesAndTool) {
    RunSettings settings;
    settings.parameters[129] = 12;
    settings.variables[100] = 7;
    settings.tool = 4;
    auto run = runM350(lines({"#60 = #629", "#61 = #100", "#62 = #1300", "M30"}), settings);
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(60), 12);
    EXPECT_DOUBLE_EQ(run.number(61), 7);
    EXPECT_DOUBLE_EQ(run.number(62), 4);
    EXPECT_EQ(run.report.tool, 4);
}

TEST(ControllerM350, MdiLinesRun) {
    Controller c(m350Machine(), RunSettings{});
    ASSERT_TRUE(c.loadMdi({"#100 = 3", "#101 = #100 * 2", "G90 G00 X5 Y-2"}));
    RunReport r = c.run();
    EXPECT_EQ(r.status, RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(101).number, 6);
    EXPECT_NEAR(r.machine(0), 5, kEps);
    EXPECT_NEAR(r.machine(1), -2, kEps);
    EXPECT_DOUBLE_EQ(c.variable(880).number, 5);

    Controller failing(m350Machine(), RunSettings{});
    ASSERT_TRUE(failing.loadMdi({"#100 = 1", "#101 = 1 / 0"}));
    RunReport alarmed = failing.run();
    EXPECT_EQ(alarmed.status, RunStatus::Alarm);
    ASSERT_TRUE(alarmed.alarm);
    EXPECT_EQ(alarmed.alarm->code, AlarmCode::DivisionByZero);
    EXPECT_EQ(alarmed.alarm->file, "MDI");
    EXPECT_EQ(alarmed.alarm->line, 2u);
    EXPECT_DOUBLE_EQ(failing.variable(100).number, 1);
}

TEST(ControllerM350, SyntaxErrorPreventsTheRun) {
    auto run = loadProgram(m350Machine(), lines({"#100 = 1", "#101 = [2 + ", "M30"}));
    EXPECT_FALSE(run.loaded);
    ASSERT_FALSE(run.controller->diagnostics().empty());
    EXPECT_EQ(run.controller->diagnostics().front().line, 2u);
    RunReport r = run.controller->run();
    EXPECT_EQ(r.status, RunStatus::Error);
    EXPECT_DOUBLE_EQ(run.number(100), 0); // nothing ran
}

TEST(ControllerFanuc, MachinePositionAndDwellInSeconds) {
    auto run = runFanuc(lines({"G90 G00 X10 Y-4", "#100 = #5021", "#101 = #5022", "#102 = #5041", "G04 X2", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 10);
    EXPECT_DOUBLE_EQ(run.number(101), -4);
    EXPECT_DOUBLE_EQ(run.number(102), 10);
    // the 10.77 mm rapid never reaches G00 speed at 500 mm/s^2: a triangle of 2*sqrt(L/a) seconds;
    // then the 2 s dwell and 0.1 ms for each of the 6 blocks
    double rapid = 2.0 * std::sqrt(std::sqrt(116.0) / 500.0);
    EXPECT_NEAR(run.report.simTime, rapid + 2.0 + 6 * 1e-4, 1e-9);
    EXPECT_TRUE(run.controller->variable(9999).vacant); // undefined reads as vacant
}

// ---------------------------------------------------------------- alarms, both dialects

struct AlarmCase {
    const char* name;
    std::vector<std::string> body; // line 1 is `#100 = 1`; the alarm is on `line`
    AlarmCode code;
    std::uint32_t line;
};

void checkAlarms(bool fanuc, const std::vector<AlarmCase>& cases) {
    for (const AlarmCase& c : cases) {
        SCOPED_TRACE(std::string(fanuc ? "fanuc: " : "m350: ") + c.name);
        std::string text;
        for (const std::string& line : c.body) {
            text += line + "\n";
        }
        auto run = fanuc ? runFanuc(text) : runM350(text);
        EXPECT_EQ(run.report.status, RunStatus::Alarm);
        ASSERT_TRUE(run.report.alarm);
        EXPECT_EQ(alarmKey(run.report.alarm->code), alarmKey(c.code)) << run.alarmText();
        EXPECT_EQ(run.report.alarm->file, run.fileName);
        EXPECT_EQ(run.report.alarm->line, c.line) << run.alarmText();
        EXPECT_FALSE(run.report.alarm->message.empty());
        EXPECT_FALSE(run.vacant(100));
        EXPECT_DOUBLE_EQ(run.number(100), 1); // set before the alarm, still inspectable
        EXPECT_DOUBLE_EQ(run.number(102), 0); // after the alarm: never ran
    }
}

std::vector<AlarmCase> commonAlarmCases(const char* readOnlyWrite, const char* indirectReadOnlyWrite) {
    return {
        {"division by zero", {"#100 = 1", "#101 = 1 / [#100 - 1]", "#102 = 1", "M30"}, AlarmCode::DivisionByZero, 2},
        {"computed GOTO to a missing N", {"#100 = 1", "#1 = 77", "GOTO #1", "#102 = 1", "N78 M30"},
         AlarmCode::GotoMissingLabel, 3},
        {"computed GOTO[expr]", {"#100 = 1", "#102 = 0", "GOTO[#100 + 1]", "#102 = 1", "M30"},
         AlarmCode::GotoMissingLabel, 3},
        {"GOTO to an N of another program", {"#100 = 1", "M98 P100", "N5 #102 = 1", "M30", "O100", "GOTO 5", "M99"},
         AlarmCode::GotoMissingLabel, 6},
        {"indirect write to a read-only variable", {"#100 = 1", "#1 = 1", indirectReadOnlyWrite, "#102 = 1", "M30"},
         AlarmCode::ReadOnlyVariable, 3},
        {"END without DO", {"#100 = 1", "#101 = 2", "END1", "#102 = 1", "M30"}, AlarmCode::EndWithoutDo, 3},
        {"read-only variable", {"#100 = 1", readOnlyWrite, "#102 = 1", "M30"}, AlarmCode::ReadOnlyVariable, 2},
        {"M98 calls itself",
         {"#100 = 1", "M98 P100", "#102 = 1", "M30", "O100", "#101 = #101 + 1", "M98 P100", "M99"},
         AlarmCode::CallNestingTooDeep, 7},
        {"unknown O program", {"#100 = 1", "M98 P9999", "#102 = 1", "M30"}, AlarmCode::UnknownProgram, 2},
        {"SQRT of a negative number", {"#100 = 1", "#101 = SQRT[-4]", "#102 = 1", "M30"}, AlarmCode::InvalidArgument,
         2},
        {"alarm inside a subprogram", {"#100 = 1", "M98 P100", "#102 = 1", "M30", "O100", "#101 = 2 / 0", "M99"},
         AlarmCode::DivisionByZero, 6},
    };
}

TEST(ControllerAlarms, M350) {
    checkAlarms(false, commonAlarmCases("#1520 = 1", "#[1520 + #1 - 1] = 1"));
}

TEST(ControllerAlarms, Fanuc) {
    auto cases = commonAlarmCases("#5021 = 1", "#[5020 + #1] = 1");
    cases.push_back({"G65 calls itself",
                     {"#100 = 1", "G65 P100", "#102 = 1", "M30", "O100", "#101 = #101 + 1", "G65 P100", "M99"},
                     AlarmCode::CallNestingTooDeep, 7});
    cases.push_back({"#0 is read-only", {"#100 = 1", "#0 = 1", "#102 = 1", "M30"}, AlarmCode::ReadOnlyVariable, 2});
    cases.push_back({"macro alarm", {"#100 = 1", "#3000=7(STOP HERE)", "#102 = 1", "M30"}, AlarmCode::MacroAlarm, 2});
    checkAlarms(true, cases);
}

TEST(ControllerAlarms, SelfCallStopsAtTheDialectsDepth) {
    auto text = lines({"M98 P100", "M30", "O100", "#101 = #101 + 1", "M98 P100", "M99"});
    auto m350Run = runM350(text);
    auto fanucRun = runFanuc(text);
    ASSERT_TRUE(m350Run.report.alarm);
    ASSERT_TRUE(fanucRun.report.alarm);
    // each level ran its first line once before the call that was one too many
    EXPECT_DOUBLE_EQ(m350Run.number(101), m350::gcode::Dialect::m350().maxCallDepth);
    EXPECT_DOUBLE_EQ(fanucRun.number(101), m350::gcode::Dialect::fanuc().maxCallDepth);
}

} // namespace
