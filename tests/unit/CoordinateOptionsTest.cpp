// FANUC's coordinate options: the additional work systems G54.1 P1-Pn with their offsets (G10 L20,
// #7001.., #14001..), the coordinate system rotation G68 / G69, and the common variables a machine
// declares (machine.toml [variables] common). Through the Controller on a FANUC 0i as the dialect
// has it (48 systems, G68) and on the bundled 30i (300 systems, the added variables).
#include "RunProgram.h"

#include "core/macro/VariableStore.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;

constexpr double kTolerance = 1e-9;

config::MachineConfig fanuc30i() { return bundledMachine("fanuc-30i"); }

// ------------------------------------------------------------------ G54.1 and G10 L20

TEST(AdditionalWorkSystems, G54_1SelectsTheSystemThatG10L20Wrote) {
    auto run = runFanuc(lines({"G10 L20 P3 X100 Y50 Z-10", "G54.1 P3", "G90 G00 X0 Y0 Z0", "#100 = #5021",
                               "#101 = #5022", "#102 = #5023", "#103 = #4014", "#104 = #4130", "#105 = #7041",
                               "#106 = #7043", "G54 X0", "#107 = #5021", "#108 = #4130", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 100);
    EXPECT_DOUBLE_EQ(run.number(101), 50);
    EXPECT_DOUBLE_EQ(run.number(102), -10);
    EXPECT_NEAR(run.number(103), 54.1, kTolerance);
    EXPECT_DOUBLE_EQ(run.number(104), 3);
    EXPECT_DOUBLE_EQ(run.number(105), 100); // #7001 + 20 x 2 + 0: P3 X
    EXPECT_DOUBLE_EQ(run.number(106), -10);
    EXPECT_DOUBLE_EQ(run.number(107), 0); // back in G54, whose offset is 0
    EXPECT_DOUBLE_EQ(run.number(108), 0);
}

TEST(AdditionalWorkSystems, WritingItsVariablesMovesTheActiveSystem) {
    auto run = runFanuc(lines({"G54.1 P48", "G90 G00 X1 Y2", "#7941 = 10", "#7942 = 20", "#100 = #5041",
                               "G00 X1 Y2", "#101 = #5021", "#102 = #5022", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), -9); // the tool stands where it stood; P48 moved under it
    EXPECT_DOUBLE_EQ(run.number(101), 11);
    EXPECT_DOUBLE_EQ(run.number(102), 22);
}

TEST(AdditionalWorkSystems, WithoutPItIsP1) {
    auto run = runFanuc(lines({"#7001 = 5", "G54.1", "#100 = #4130", "G90 G00 X0", "#101 = #5021", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 1);
    EXPECT_DOUBLE_EQ(run.number(101), 5);
}

TEST(AdditionalWorkSystems, APBeyondTheMachinesSystemsIsAnAlarmAtP) {
    auto run = runFanuc(lines({"G00 X0", "G54.1 P49", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.report.alarm->column, 7u);
    EXPECT_EQ(run.report.alarm->message, "P49: G54.1 selects the additional work systems P1-P48 of this machine "
                                         "(machine.toml [coordinates] additional_systems)");
    auto l20 = runFanuc(lines({"G10 L20 P49 X1", "M30"}));
    ASSERT_EQ(l20.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(l20.report.alarm->message, "G10: G10 L20 writes the additional work systems P1-P48 (G54.1) of this machine");
}

TEST(AdditionalWorkSystems, A0iHasNoVariablesBeyondP48) {
    auto run = runFanuc(lines({"#100 = #7941", "#101 = #14001", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->line, 2u);
    EXPECT_EQ(run.report.alarm->message, "#14001 does not exist in the fanuc dialect");
}

TEST(AdditionalWorkSystems, The30iHas300AndTheirSecondNumbers) {
    auto run = runProgram(fanuc30i(), lines({"G10 L20 P300 X7 Y8", "G10 L20 P1 Z-3", "#100 = #19981", "#101 = #19982",
                                             "#102 = #14003", "#103 = #7003", "#14001 = 4", "#104 = #7001",
                                             "G54.1 P300", "G90 G00 X0 Y0", "#105 = #5021", "#106 = #5022", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 7);
    EXPECT_DOUBLE_EQ(run.number(101), 8);
    EXPECT_DOUBLE_EQ(run.number(102), -3); // #14001.. and #7001.. are the same offsets for P1-P48
    EXPECT_DOUBLE_EQ(run.number(103), -3);
    EXPECT_DOUBLE_EQ(run.number(104), 4);
    EXPECT_DOUBLE_EQ(run.number(105), 7);
    EXPECT_DOUBLE_EQ(run.number(106), 8);
}

TEST(AdditionalWorkSystems, AMachineWithoutThemRefusesG54_1AndL20) {
    config::MachineConfig machine = fanucMachine();
    machine.variableLayout.additionalWorkSystems = 0;
    auto run = runProgram(machine, lines({"G54.1 P1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "G54.1: not a G code this machine knows");
    auto l20 = runProgram(machine, lines({"G10 L20 P1 X0", "M30"}));
    ASSERT_EQ(l20.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(l20.report.alarm->message.find("which this machine does not have"), std::string::npos)
        << l20.alarmText();
}

TEST(AdditionalWorkSystems, TheM350HasNone) {
    auto run = runM350(lines({"G54.1 P1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "G54.1: not a G code this machine knows");
}

TEST(AdditionalWorkSystems, ThePanelNamesTheSystem) {
    auto run = runFanuc(lines({"G54.1 P7", "M30"}));
    EXPECT_RUN_OK(run);
    const controller::PanelStatus status = run.controller->panelStatus();
    EXPECT_EQ(controller::workSystemName(status.workSystem), "G54.1 P7");
    EXPECT_NE(status.modalLine.find(" G54.1 P7 "), std::string::npos) << status.modalLine;
    EXPECT_EQ(controller::workSystemName(0), "G92");
    EXPECT_EQ(controller::workSystemName(6), "G59");
}

// ------------------------------------------------------------------ G68 / G69

// Machine X Y after the program (work offsets 0).
struct Xy {
    double x;
    double y;
};

Xy endOf(const ProgramRun& run) {
    return {run.number(5021), run.number(5022)};
}

TEST(CoordinateRotation, AbsoluteMovesTurnAboutTheCentre) {
    auto run = runFanuc(lines({"G90 G00 X0 Y0", "G68 X10 Y0 R90", "G01 X20 Y0 F500", "#100 = #5021",
                               "#101 = #5022", "#102 = #4016", "G69", "#103 = #4016", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(100), 10, kTolerance);
    EXPECT_NEAR(run.number(101), 10, kTolerance);
    EXPECT_DOUBLE_EQ(run.number(102), 68);
    EXPECT_DOUBLE_EQ(run.number(103), 69);
}

TEST(CoordinateRotation, IncrementalMovesTurnWithTheProgram) {
    auto run = runFanuc(lines({"G90 G00 X3 Y4", "G68 X0 Y0 R90", "G91 G01 X5 F500", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(endOf(run).x, 3, kTolerance);
    EXPECT_NEAR(endOf(run).y, 9, kTolerance);
}

// FANUC: until an absolute command, the program turns about where the tool stood at G68; a plane
// axis left out of that first absolute command reads from there.
TEST(CoordinateRotation, BeforeTheFirstAbsoluteCommandTheToolIsTheCentre) {
    auto run = runFanuc(lines({"G90 G00 X5 Y0", "G68 X0 Y0 R90", "G91 G01 X10 F500", "#100 = #5021",
                               "#101 = #5022", "G90 X20", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(100), 5, kTolerance);
    EXPECT_NEAR(run.number(101), 10, kTolerance);
    // programmed Y is still 0 (where the tool stood), X is 20: turned about X0 Y0 -> X0 Y20
    EXPECT_NEAR(endOf(run).x, 0, kTolerance);
    EXPECT_NEAR(endOf(run).y, 20, kTolerance);
}

TEST(CoordinateRotation, AnAxisLeftOutKeepsItsProgrammedValue) {
    auto run = runFanuc(lines({"G90 G00 X0 Y0", "G68 X0 Y0 R90", "G00 X10 Y5", "G01 X20 F500", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(endOf(run).x, -5, kTolerance); // X20 Y5 turned by 90
    EXPECT_NEAR(endOf(run).y, 20, kTolerance);
}

TEST(CoordinateRotation, ArcsTurnTheirCentreToo) {
    // a half circle from X10 Y0 about X0 Y0 to X-10 Y0, turned by 90: it ends at X0 Y-10 and goes
    // through X-10 Y0 (counter-clockwise), the same length as unturned
    auto run = runFanuc(lines({"G90 G00 X0 Y10", "G68 X0 Y0 R90", "G00 X10 Y0", "G03 X-10 Y0 I-10 J0 F1000", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(endOf(run).x, 0, kTolerance);
    EXPECT_NEAR(endOf(run).y, -10, kTolerance);
    auto byRadius = runFanuc(lines({"G90 G00 X0 Y0", "G68 X0 Y0 R180", "G00 X10 Y0", "G02 X0 Y10 R10 F1000", "M30"}));
    EXPECT_RUN_OK(byRadius);
    EXPECT_NEAR(endOf(byRadius).x, 0, kTolerance);
    EXPECT_NEAR(endOf(byRadius).y, -10, kTolerance);
}

TEST(CoordinateRotation, CannedCycleHolesTurn) {
    auto run = runFanuc(lines({"G90 G00 X0 Y0 Z10", "G68 X0 Y0 R90", "G98 G81 X10 Y0 Z-5 R2 F200", "#100 = #5021",
                               "#101 = #5022", "G91 X0 Y10", "G80", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(100), 0, kTolerance);
    EXPECT_NEAR(run.number(101), 10, kTolerance);
    EXPECT_NEAR(endOf(run).x, -10, kTolerance);
    EXPECT_NEAR(endOf(run).y, 10, kTolerance);
}

TEST(CoordinateRotation, TheDroStaysInTheUnturnedWorkSystem) {
    auto run = runFanuc(lines({"G10 L2 P1 X100 Y100", "G54 G90 G00 X0 Y0", "G68 X0 Y0 R90", "G00 X10 Y0",
                               "#100 = #5041", "#101 = #5042", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(100), 0, kTolerance);
    EXPECT_NEAR(run.number(101), 10, kTolerance);
    const controller::PanelStatus status = run.controller->panelStatus();
    EXPECT_NEAR(status.work(0), 0, kTolerance);
    EXPECT_NEAR(status.work(1), 10, kTolerance);
}

// Where every move of a run ends (machine X Y).
class MoveEnds final : public machine::MachineObserver {
public:
    void onMachineEvent(const machine::MachineEvent& event) override {
        if (event.type == machine::MachineEvent::Type::Rapid || event.type == machine::MachineEvent::Type::Feed ||
            event.type == machine::MachineEvent::Type::Arc) {
            ends.push_back({event.to(0), event.to(1)});
        }
    }
    std::vector<Xy> ends;
};

// Cutter compensation follows the turned path: every corner of the same contour turned by 90 degrees
// is the unturned one's, turned.
TEST(CoordinateRotation, CutterCompensationActsOnTheTurnedPath) {
    const std::string contour = lines({"G41 D1 G01 X10 Y0 F500", "G01 X10 Y20", "G03 X30 Y20 I10 J0", "G01 X30 Y0",
                                       "G40 G01 X40 Y-10", "M30"});
    MoveEnds plainEnds;
    MoveEnds turnedEnds;
    controller::RunSettings plainSettings;
    plainSettings.observer = &plainEnds;
    controller::RunSettings turnedSettings;
    turnedSettings.observer = &turnedEnds;
    auto plain = runFanuc(lines({"G10 L11 P1 R2", "G90 G00 X0 Y0"}) + contour, plainSettings);
    auto turned = runFanuc(lines({"G10 L11 P1 R2", "G90 G00 X0 Y0", "G68 X0 Y0 R90"}) + contour, turnedSettings);
    EXPECT_RUN_OK(plain);
    EXPECT_RUN_OK(turned);
    ASSERT_EQ(plainEnds.ends.size(), turnedEnds.ends.size());
    ASSERT_GE(plainEnds.ends.size(), 6u);
    for (std::size_t i = 0; i < plainEnds.ends.size(); ++i) {
        EXPECT_NEAR(turnedEnds.ends[i].x, -plainEnds.ends[i].y, 1e-6) << "move " << i;
        EXPECT_NEAR(turnedEnds.ends[i].y, plainEnds.ends[i].x, 1e-6) << "move " << i;
    }
}

TEST(CoordinateRotation, ReferenceReturnsAndSystemChangesAreRefusedUntilG69) {
    struct Case {
        const char* block;
        std::uint32_t column;
        const char* starts;
    };
    for (const Case& c : {Case{"G91 G28 Z0", 5, "G28: returns to a reference position while G68 turns the program"},
                          Case{"G30 P2 Z0", 1, "G30: returns to a reference position"},
                          Case{"G55", 1, "G55: changes the coordinate system"},
                          Case{"G54.1 P2", 1, "G54.1: changes the coordinate system"},
                          Case{"G92 X0", 1, "G92: changes the coordinate system"},
                          Case{"G52 X5", 1, "G52: changes the coordinate system"},
                          Case{"G18", 1, "G18: the plane of a rotation stays until G69"}}) {
        auto run = runFanuc(lines({"G68 X0 Y0 R30", c.block, "M30"}));
        ASSERT_EQ(run.report.status, controller::RunStatus::Alarm) << c.block;
        EXPECT_EQ(run.report.alarm->line, 2u) << c.block;
        EXPECT_EQ(run.report.alarm->column, c.column) << c.block;
        EXPECT_EQ(run.report.alarm->message.rfind(c.starts, 0), 0u) << run.alarmText();
    }
    auto cancelled = runFanuc(lines({"G68 X0 Y0 R30", "G69 G91 G28 Z0", "G90 G55 G17", "M30"}));
    EXPECT_RUN_OK(cancelled);
}

TEST(CoordinateRotation, G68TakesThePlanesAxesAndR) {
    auto run = runFanuc(lines({"G68 X0 Y0 Z5 R30", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->column, 11u);
    EXPECT_EQ(run.report.alarm->message,
              "Z5: G68 takes the centre of rotation on the plane's axes (X Y) and R, the angle; this is no move");
    auto threeD = runFanuc(lines({"G68 X0 Y0 Z0 I0 J0 K1 R30", "M30"}));
    ASSERT_EQ(threeD.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(threeD.report.alarm->message.find("three-dimensional coordinate conversion"), std::string::npos);
}

TEST(CoordinateRotation, TheZxPlaneTurnsZTowardX) {
    auto run = runFanuc(lines({"G90 G00 X0 Y0 Z0", "G18 G68 X0 Z0 R90", "G01 Z10 F500", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(endOf(run).x, 10, kTolerance);
    EXPECT_NEAR(run.number(5023), 0, kTolerance);
}

TEST(CoordinateRotation, ProgramEndAndResetCancelIt) {
    auto run = runFanuc(lines({"G68 X0 Y0 R45", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(4016), 69);
    auto alarmed = runFanuc(lines({"G68 X0 Y0 R45", "#1 = 1 / 0", "M30"}));
    ASSERT_EQ(alarmed.report.status, controller::RunStatus::Alarm);
    EXPECT_DOUBLE_EQ(alarmed.number(4016), 68);
    alarmed.controller->reset();
    EXPECT_DOUBLE_EQ(alarmed.number(4016), 69);
}

TEST(CoordinateRotation, AMachineWithoutItAndTheM350RefuseG68AndG69) {
    config::MachineConfig machine = fanucMachine();
    machine.coordinateRotation = false;
    for (const char* code : {"G68 X0 Y0 R10", "G69"}) {
        auto fanuc = runProgram(machine, lines({code, "M30"}));
        ASSERT_EQ(fanuc.report.status, controller::RunStatus::Alarm) << code;
        EXPECT_NE(fanuc.report.alarm->message.find("not a G code this machine knows"), std::string::npos);
        auto m350 = runM350(lines({code, "M30"}));
        ASSERT_EQ(m350.report.status, controller::RunStatus::Alarm) << code;
        EXPECT_NE(m350.report.alarm->message.find("not a G code this machine knows"), std::string::npos);
    }
}

// ------------------------------------------------------------------ common variables

TEST(CommonVariables, The30iHasTheAddedRanges) {
    auto run = runProgram(fanuc30i(), lines({"#499 = 1", "#300 = 2", "#98000 = 3", "#98499 = 4", "#100 = #300",
                                             "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 2);
    EXPECT_DOUBLE_EQ(run.number(98499), 4);
    auto beyond = runProgram(fanuc30i(), lines({"#1 = 1", "#98500 = 1", "M30"}));
    ASSERT_EQ(beyond.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(beyond.report.alarm->line, 2u);
    EXPECT_EQ(beyond.report.alarm->column, 1u);
    EXPECT_EQ(beyond.report.alarm->message,
              "#98500 does not exist in the fanuc dialect (this machine's common variables are #100-#499, #500-#999, "
              "#98000-#98499: machine.toml [variables] common)");
}

TEST(CommonVariables, A0iHasOnlyItsOwn) {
    auto run = runFanuc(lines({"#300 = 1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "#300 does not exist in the fanuc dialect (this machine's common variables "
                                         "are #100-#199, #500-#999: machine.toml [variables] common)");
    auto far = runFanuc(lines({"#1 = #[98000]", "M30"}));
    ASSERT_EQ(far.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(far.report.alarm->message, "#98000 does not exist in the fanuc dialect (this machine's common "
                                         "variables are #100-#199, #500-#999: machine.toml [variables] common)");
    auto beyond = runFanuc(lines({"#1 = #[1000000]", "M30"}));
    ASSERT_EQ(beyond.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(beyond.report.alarm->message, "#[1000000]: variable numbers are whole numbers from 0 to 999999");
}

TEST(CommonVariables, ResetClearsThoseBelow500AndKeepsTheOthers) {
    params::ParameterTable parameters;
    macro::VariableLayout layout;
    layout.common = {{100, 499}, {500, 999}, {98000, 98499}};
    macro::VariableStore store(gcode::Dialect::fanuc(), parameters, layout);
    for (int n : {300, 700, 98123}) {
        store.write(store.map().describe(n), n, macro::Value::of(n));
    }
    EXPECT_EQ(store.map().describe(300).kind, macro::VariableKind::Common);
    EXPECT_EQ(store.map().describe(98123).kind, macro::VariableKind::Retained);
    store.reset();
    EXPECT_TRUE(store.read(store.map().describe(300), 300).vacant);
    EXPECT_DOUBLE_EQ(store.read(store.map().describe(700), 700).number, 700);
    EXPECT_DOUBLE_EQ(store.read(store.map().describe(98123), 98123).number, 98123);
}

TEST(CommonVariables, DeclaredRangesMustBeCommonAreasAndApart) {
    using macro::VariableLayout;
    EXPECT_EQ(VariableLayout::refusedCommon({{100, 499}, {500, 999}, {98000, 98499}}), std::nullopt);
    EXPECT_EQ(VariableLayout::refusedCommon({{100, 1200}}).value_or(Message{}).english(),
              "#100-#1200 is not a common variable range: they lie within #100-#999 or #20000-#999999 (the numbers "
              "between are system variables)");
    EXPECT_EQ(VariableLayout::refusedCommon({{100, 499}, {400, 600}}).value_or(Message{}).english(), "#100-#499 and #400-#600 overlap");
    EXPECT_EQ(VariableLayout::refusedCommon({{600, 500}}).value_or(Message{}).english(), "#600-#500 runs backwards");
}

} // namespace
