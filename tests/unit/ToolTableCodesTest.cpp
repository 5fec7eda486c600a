// LinuxCNC's G10 L1 / L10 / L11 on a FANUC machine write the tool table as LinuxCNC does, with
// values computed here by hand; G43 and G10 in one block follow the documented modal order (the
// old length applies, then the table changes); touch off on both machines; the FANUC offset
// memory (#2001, G10 L11 P R, H, D) is the table.
#include "RunProgram.h"

#include "core/tools/ToolTableFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;
using testing::HasSubstr;

config::MachineConfig fanucWithTable(const std::string& tbl = "T1 P1 Z0 ;end mill\nT2 P2\n") {
    config::MachineConfig cfg = fanucMachine();
    cfg.toolTable = tools::parseToolTable(tbl, "tool.tbl").table;
    return cfg;
}

tools::ToolEntry row(const ProgramRun& run, int tool) {
    const tools::ToolTable table = run.controller->toolTableEdits().table();
    const tools::ToolEntry* found = table.find(tool);
    EXPECT_NE(found, nullptr) << "tool " << tool;
    return found ? *found : tools::ToolEntry{};
}

// G54 Z-100, X10 Y20; the spindle nose at work X0 Y0 Z0 = machine (10, 20, -100).
const std::string kSetup = lines({"G10 L2 P1 X10 Y20 Z-100", "G90 G54 G00 X0 Y0 Z0"});

TEST(ToolTableCodes, L1WritesTheValuesAsGivenAndG91ChangesNothing) {
    auto run = runProgram(fanucWithTable(), kSetup + lines({"G10 L1 P1 Z50 R3", "#100 = #2001",
                                                             "G91 G10 L1 P2 X1.5 Z5 I10 J20 Q3", "G90", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 50.0) << "offset memory 1 is tool 1's Z";
    EXPECT_DOUBLE_EQ(row(run, 1).offset(tools::kZ), 50.0);
    EXPECT_DOUBLE_EQ(*row(run, 1).diameter, 6.0) << "R is the radius";
    EXPECT_EQ(row(run, 1).comment, "end mill") << "the row keeps its other columns";
    const tools::ToolEntry t2 = row(run, 2);
    EXPECT_DOUBLE_EQ(t2.offset(0), 1.5);
    EXPECT_DOUBLE_EQ(t2.offset(tools::kZ), 5.0) << "absolute under G91, as in LinuxCNC";
    EXPECT_DOUBLE_EQ(*t2.frontAngle, 10.0);
    EXPECT_DOUBLE_EQ(*t2.backAngle, 20.0);
    EXPECT_EQ(*t2.orientation, 3);
}

TEST(ToolTableCodes, L10MakesTheCurrentPositionReadTheValueInTheActiveSystem) {
    // tool 1 at Z50 applied: machine Z = 5 - 100 + 50 = -45
    auto run = runProgram(fanucWithTable(),
                          kSetup + lines({"G10 L1 P1 Z50", "G43 H1 Z5", "#100 = #5023", "#101 = #5043",
                                          "G10 L10 P1 Z2 X3", "#102 = #2001", "#103 = #5043", "G43 H1",
                                          "#104 = #5043", "G92 Z0", "G10 L10 P1 Z4", "#105 = #2001", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), -45.0);
    EXPECT_DOUBLE_EQ(run.number(101), 5.0);
    // Z: -45 - (-100) - 2 = 53; X: 10 - 10 - 3 = -3
    EXPECT_DOUBLE_EQ(run.number(102), 53.0);
    EXPECT_DOUBLE_EQ(row(run, 1).offset(0), -3.0);
    EXPECT_DOUBLE_EQ(run.number(103), 5.0) << "the applied length changes only with the next G43 or H";
    EXPECT_DOUBLE_EQ(run.number(104), 2.0) << "G43 H1 again: the position reads the value given";
    // G92 Z0 there adds 2 to the work offsets: -45 - (-100 + 2) - 4 = 49
    EXPECT_DOUBLE_EQ(run.number(105), 49.0);
}

TEST(ToolTableCodes, L11CountsFromMachineZeroWithoutG92OrTheWorkSystem) {
    auto run = runProgram(fanucWithTable(), kSetup + lines({"G92 X0 Z0", "G10 L11 P2 X1 Z7", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(row(run, 2).offset(tools::kZ), -107.0) << "-100 - 7: LinuxCNC's fixture 9 is machine zero here";
    EXPECT_DOUBLE_EQ(row(run, 2).offset(0), 9.0);
}

TEST(ToolTableCodes, G43AndG10L10InOneBlockApplyTheOldLengthThenChangeTheTable) {
    // LinuxCNC's order: G43 (step 18) before G10 (step 23), whatever the order of the words. The
    // pitfall: the display does not show the touched-off value until a second G43.
    for (const char* block : {"G43 H1 G10 L10 P1 Z1", "G10 L10 P1 Z1 G43 H1"}) {
        auto run = runProgram(fanucWithTable("T1 P1 Z50\n"),
                              lines({"G10 L2 P1 Z-100", "G90 G54 G00 Z0", "G43 H1 Z0", "#100 = #5023", block,
                                     "#101 = #2001", "#102 = #5043", "G43 H1", "#103 = #5043", "M30"}));
        ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << block << ": " << run.alarmText();
        EXPECT_DOUBLE_EQ(run.number(100), -50.0) << block;
        EXPECT_DOUBLE_EQ(run.number(101), 49.0) << block << ": -50 - (-100) - 1";
        EXPECT_DOUBLE_EQ(run.number(102), 0.0) << block << ": tool 1's old 50 still applies";
        EXPECT_DOUBLE_EQ(run.number(103), 1.0) << block << ": the next G43 applies 49";
    }
}

TEST(ToolTableCodes, G10ToolCodesRefuseWhatLinuxCncRefuses) {
    struct Case {
        const char* block;
        const char* message;
    };
    for (const Case& c : {Case{"G10 L1 P9 Z1", "tool 9 is not in the tool table"},
                          Case{"G10 L1 P1", "G10 L1 needs R<value> (FANUC: G10 L1 P<offset> R..) or axis words"},
                          Case{"G10 L10 P0 Z1", "P is the tool number"},
                          Case{"G10 L1 P1 Q12", "the orientation Q runs from 0 to 9"}}) {
        auto run = runProgram(fanucWithTable(), lines({"G10 L1 P1 Z7", c.block, "M30"}));
        ASSERT_EQ(run.report.status, controller::RunStatus::Alarm) << c.block;
        EXPECT_THAT(run.alarmText(), HasSubstr(c.message)) << c.block;
        EXPECT_THAT(run.alarmText(), HasSubstr(":2:")) << c.block;
        EXPECT_DOUBLE_EQ(run.controller->toolTableEdits().table().find(1)->offset(tools::kZ), 7.0) << "a refused block changes nothing";
    }
    auto m350 = runM350(lines({"G10 L1 P1 Z5", "M30"}));
    EXPECT_THAT(m350.alarmText(), HasSubstr("not available on the M350"));
}

TEST(ToolTableCodes, TheOffsetMemoryIsTheTable) {
    // #2003 / G10 L11 P R make the row; D reads the radius of a row with D, else the one value
    auto run = runProgram(fanucWithTable("T5 P5 Z40 D8\n"),
                          lines({"G10 L11 P3 R125.5", "#2004 = 2", "G91 G10 L11 P3 R0.5", "G90", "#100 = #2003",
                                 "#101 = #2005", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Ok) << run.alarmText();
    EXPECT_DOUBLE_EQ(run.number(100), 126.0);
    EXPECT_DOUBLE_EQ(run.number(101), 40.0);
    tools::ToolTable table = run.controller->toolTableEdits().table();
    ASSERT_NE(table.find(3), nullptr);
    EXPECT_EQ(table.find(3)->pocket, 3);
    EXPECT_DOUBLE_EQ(table.find(4)->offset(tools::kZ), 2.0);
    params::ParameterTable parameters;
    tools::ToolData data(gcode::Dialect::fanuc(), parameters, tools::parseToolTable("T5 P5 Z40 D8\n", "t").table);
    ASSERT_EQ(data.setOffsetVariable(4, 2.0), std::nullopt);
    EXPECT_DOUBLE_EQ(data.radiusOffset(5), 4.0) << "D5: tool 5's diameter / 2";
    EXPECT_DOUBLE_EQ(data.radiusOffset(4), 2.0) << "D4: row 4 has no D, so its one value is the radius";
    EXPECT_DOUBLE_EQ(data.radiusOffset(6), 0.0);
    ASSERT_EQ(data.setOffsetVariable(7, 0.0), std::nullopt);
    EXPECT_EQ(data.table().find(7), nullptr) << "an offset of 0 makes no row";
}

TEST(ToolTableCodes, TouchOffOnTheM350WritesTheToolsParameterAndTheDisplayReadsTheValue) {
    config::MachineConfig cfg = m350Machine();
    cfg.parameters.set(930, -50.0);
    cfg.offsets[1][2] = -20.0; // G54 Z
    controller::RunSettings settings;
    settings.tool = 1;
    controller::Controller c(cfg, settings);
    ASSERT_TRUE(c.loadMdi({"G53 Z-80"}));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(852).number, -10.0) << "-80 - (-20) - (-50)";
    Message why;
    ASSERT_TRUE(c.toolTableEdits().touchOffTool(5.0, &why)) << why;
    EXPECT_DOUBLE_EQ(c.parameter(930), -65.0) << "-80 - (-20) - 5";
    EXPECT_DOUBLE_EQ(c.variable(1430).number, -65.0);
    EXPECT_DOUBLE_EQ(c.toolTableEdits().table().find(1)->offset(tools::kZ), -65.0);
    EXPECT_DOUBLE_EQ(c.variable(852).number, 5.0) << "the display shows the measured value at once";
    EXPECT_TRUE(c.toolTableEdits().changed());
}

TEST(ToolTableCodes, TouchOffRefusesAnEmptySpindleAToolWithoutAParameterAndARun) {
    controller::RunSettings settings;
    settings.tool = 0;
    controller::Controller empty(m350Machine(), settings);
    Message why;
    EXPECT_FALSE(empty.toolTableEdits().touchOffTool(0.0, &why));
    EXPECT_THAT(why.english(), HasSubstr("empty"));
    settings.tool = 40; // capacity 16 + 20 virtual tools: 36 at most
    controller::Controller beyond(m350Machine(), settings);
    EXPECT_FALSE(beyond.toolTableEdits().touchOffTool(0.0, &why));
    EXPECT_THAT(why.english(), HasSubstr("tool 40 has no Z offset parameter"));
    EXPECT_EQ(why.in(MessageLanguage::Chinese), // the Probe page says it in the panel's language
              "刀具40在本M350上没有Z偏置参数（刀库刀具为参数930-945，超出容量的20把虚拟刀具为973-992）");
    settings.tool = 1;
    controller::Controller running(m350Machine(), settings);
    ASSERT_TRUE(running.loadMdi({"G04 P5000"}));
    ASSERT_TRUE(running.start());
    running.advance(0.5);
    EXPECT_FALSE(running.toolTableEdits().touchOffTool(0.0, &why));
    EXPECT_THAT(why.english(), HasSubstr("a program is running"));
    EXPECT_FALSE(running.toolTableEdits().touchOffTool(std::nan(""), &why));
    EXPECT_DOUBLE_EQ(running.parameter(930), 0.0);
}

TEST(ToolTableCodes, TouchOffOnAFanucWritesTheRowAndAppliesG43) {
    controller::RunSettings settings;
    settings.tool = 2;
    controller::Controller c(fanucWithTable(), settings);
    ASSERT_TRUE(c.loadMdi({"G10 L2 P1 Z-100", "G90 G54 G00 Z70"})); // machine Z -30 under G49
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    Message why;
    ASSERT_TRUE(c.toolTableEdits().touchOffTool(10.0, &why)) << why;
    EXPECT_DOUBLE_EQ(c.toolTableEdits().table().find(2)->offset(tools::kZ), 60.0) << "-30 - (-100) - 10";
    EXPECT_DOUBLE_EQ(c.variable(2002).number, 60.0);
    EXPECT_DOUBLE_EQ(c.variable(5043).number, 10.0) << "G43 H2 applied: the display reads 10";
    EXPECT_DOUBLE_EQ(c.variable(4008).number, 43.0);
    EXPECT_DOUBLE_EQ(c.variable(4111).number, 2.0);
}

} // namespace
