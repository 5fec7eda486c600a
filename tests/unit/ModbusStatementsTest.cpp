// The M350's Modbus statements against a simulated slave table: MSETDATA[slave, register, value]
// writes a holding register, MGETDATA[slave, register, #variable] reads one into a variable, with
// parameter 279 (Modbus RTU) on. modbus.toml states the slaves; MBYTE2DATA and MDATA2BYTE are
// flagged, not guessed.
#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/config/ModbusSlaves.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace {

using namespace m350;
using gcode::Dialect;
using gcode::support::listDiagnostics;
using test::lines;

// An M350 with Modbus on and slave 1 holding registers 8192 (0) and 8193 (1500), slave 7 register 0.
config::MachineConfig modbusMachine(bool enabled = true) {
    config::MachineConfig config = test::m350Machine();
    config.parameters.set(param::kModbusRtu, enabled ? 1 : 0);
    config.modbus.holding[1] = {{8192, 0}, {8193, 1500}};
    config.modbus.holding[7] = {{0, 65535}};
    return config;
}

TEST(ModbusStatements, WriteThenReadBack) {
    auto run = test::runProgram(modbusMachine(), lines({
        "MGETDATA[1, 8193, #100]",
        "MSETDATA[1, 8192, 3000]",
        "MGETDATA[1, 8192, #101]",
        "MSETDATA[1, 8192, -2]",       // two's complement: the register holds 65534
        "MGETDATA[1, 8192, #[100+2]]",
        "MGETDATA[7, 0, #103]",
        "#104 = 2",
        "MSETDATA[1, 8193, #104 * 10]",
        "MGETDATA[1, 8193, #105]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 1500);
    EXPECT_DOUBLE_EQ(run.number(101), 3000);
    EXPECT_DOUBLE_EQ(run.number(102), 65534);
    EXPECT_DOUBLE_EQ(run.number(103), 65535);
    EXPECT_DOUBLE_EQ(run.number(105), 20);
}

struct Refusal {
    const char* line;
    AlarmCode code;
    std::uint32_t column;
    const char* message;
};

TEST(ModbusStatements, RefusalsAlarmOnTheirLine) {
    const Refusal refusals[] = {
        {"MSETDATA[2, 0, 1]", AlarmCode::DeviceError, 1,
         "MSETDATA: Modbus slave 2 does not answer (the machine folder's modbus.toml has no [slave.2.holding])"},
        {"MGETDATA[1, 8200, #100]", AlarmCode::DeviceError, 1,
         "MGETDATA: slave 1 has no holding register 8200 (Modbus exception 02, illegal data address)"},
        {"MSETDATA[1, 8192, 70000]", AlarmCode::InvalidArgument, 19,
         "a 16-bit register value must be a whole number from -32768 to 65535, not 70000"},
        {"MSETDATA[1, 8192, 1.5]", AlarmCode::InvalidArgument, 19, "a 16-bit register value must be a whole number"},
        {"MSETDATA[0, 8192, 1]", AlarmCode::InvalidArgument, 10, "the slave address must be a whole number from 1 to 247"},
        {"MGETDATA[1, 8192, #1520]", AlarmCode::ReadOnlyVariable, 19, "cannot write #1520"},
    };
    for (const Refusal& r : refusals) {
        auto run = test::runProgram(modbusMachine(), lines({"#100 = 0", r.line, "M30"}));
        ASSERT_TRUE(run.report.alarm) << r.line;
        EXPECT_EQ(run.report.alarm->code, r.code) << r.line << ": " << run.alarmText();
        EXPECT_EQ(run.report.alarm->line, 2u) << r.line;
        EXPECT_EQ(run.report.alarm->column, r.column) << r.line << ": " << run.alarmText();
        EXPECT_EQ(run.report.alarm->message.rfind(r.message, 0), 0u) << run.report.alarm->message;
    }
}

TEST(ModbusStatements, ParameterTwo79OffMeansNoModbus) {
    auto run = test::runProgram(modbusMachine(false), lines({"N4 MSETDATA[1, 8192, 5]", "M30"}));
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::DeviceError);
    EXPECT_EQ(run.report.alarm->column, 4u);
    EXPECT_EQ(run.report.alarm->message, "MSETDATA: Modbus RTU is off (parameter 279 = 0)");
}

TEST(ModbusStatements, ParseErrorsNameTheColumn) {
    struct Bad {
        const char* line;
        const Dialect* dialect;
        std::uint32_t column;
        const char* message;
    };
    const Bad bad[] = {
        {"MSETDATA[1, 2]", &Dialect::m350(), 1, "MSETDATA takes 3 arguments, not 2: MSETDATA[slave, register, value]"},
        {"MGETDATA[1, 2, 100]", &Dialect::m350(), 16,
         "the third argument of MGETDATA[slave, register, #variable] is the variable that receives the register"},
        {"MGETDATA 1", &Dialect::m350(), 10, "MGETDATA must be followed by [...]: MGETDATA[slave, register, #variable]"},
        {"MSETDATA[1, 2, 3", &Dialect::m350(), 17, "missing ']' to close MSETDATA[ at column 9"},
        {"MSETDATA[1, 2, 3] X1", &Dialect::m350(), 19, "unexpected 'X' after MSETDATA[...]"},
        {"MSETDATA[1, 2, 3]", &Dialect::fanuc(), 1, "MSETDATA is an M350 Modbus statement: the fanuc dialect has none"},
        {"msetdata[1, 2, 3]", &Dialect::m350(), 1, "keywords are upper case in the m350 dialect: write MSETDATA"},
    };
    for (const Bad& b : bad) {
        gcode::support::expectOneDiagnostic(gcode::support::parse(b.line, *b.dialect), gcode::DiagnosticKind::Syntax,
                                            1, b.column, b.message, b.line);
    }
}

TEST(ModbusStatements, ConversionsAreFlaggedAndAlarmOnlyWhenReached) {
    auto p = gcode::support::parse("#1 = 1\nMBYTE2DATA[#1, #2]\nMDATA2BYTE[5]", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    for (const gcode::Diagnostic& d : p.diagnostics) {
        EXPECT_EQ(d.kind, gcode::DiagnosticKind::Lint);
        EXPECT_EQ(d.column, 1u);
        EXPECT_NE(d.message.find("is not simulated: no public document gives the meaning of its arguments"),
                  std::string::npos)
            << d.message;
    }
    auto skipped = test::runProgram(modbusMachine(), lines({"GOTO5", "MBYTE2DATA[1]", "N5 M30"}));
    EXPECT_RUN_OK(skipped);
    auto reached = test::runProgram(modbusMachine(), lines({"#1 = 1", "MDATA2BYTE[#1]", "M30"}));
    ASSERT_TRUE(reached.report.alarm);
    EXPECT_EQ(reached.report.alarm->code, AlarmCode::SuspectLine);
    EXPECT_EQ(reached.report.alarm->line, 2u);
}

TEST(ModbusStatements, BreakRunRefusesToScanATransfer) {
    controller::Controller c(modbusMachine(), {});
    ASSERT_TRUE(c.loadFile(test::writeTempFile(lines({"MSETDATA[1, 8192, 5]", "G0 X1", "G0 X2", "M30"}))));
    std::string why;
    EXPECT_FALSE(c.breakRun().startAtLine(3, &why));
    EXPECT_NE(why.find("MSETDATA talks to Modbus slave 1"), std::string::npos) << why;
}

// ---------------------------------------------------------------- modbus.toml

std::string writeModbusToml(const std::string& text) {
    std::string path = testing::TempDir() + "m350_modbus_" +
                       testing::UnitTest::GetInstance()->current_test_info()->name() + ".toml";
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(ModbusSlavesFile, ReadsSlavesAndRegisters) {
    config::ModbusSlaves slaves;
    auto problem = config::loadModbusSlaves(writeModbusToml("[slave.1.holding]\n8192 = 0\n8193 = -1\n\n"
                                                            "[slave.17]\nholding = { 0 = 42 }\n"),
                                            slaves);
    ASSERT_FALSE(problem) << *problem;
    EXPECT_EQ(slaves.holding.size(), 2u);
    EXPECT_EQ(slaves.holding[1][8192], 0);
    EXPECT_EQ(slaves.holding[1][8193], 65535);
    EXPECT_EQ(slaves.holding[17][0], 42);
}

TEST(ModbusSlavesFile, AMissingFileIsNoSlave) {
    config::ModbusSlaves slaves;
    EXPECT_FALSE(config::loadModbusSlaves(testing::TempDir() + "m350_no_such_modbus.toml", slaves));
    EXPECT_TRUE(slaves.holding.empty());
}

TEST(ModbusSlavesFile, BadEntriesNameTheirLine) {
    struct Bad {
        const char* text;
        const char* message;
    };
    const Bad bad[] = {
        {"[slave.1.holding]\n8192 = 70000\n", "line 2: slave 1 register '8192': addresses are 0-65535"},
        {"[slave.1.holding]\n70000 = 1\n", "line 2: slave 1 register '70000'"},
        {"[slave.1.holding]\n5 = 1.5\n", "line 2: slave 1 register '5'"},
        {"[slave.300.holding]\n5 = 1\n", "[slave.300] must be a slave address 1-247"},
        {"[slave.1]\nregisters = 5\n", "[slave.1] must be a slave address 1-247 with a table of holding registers"},
        {"[slave.1.holding\n", "1:"},
    };
    for (const Bad& b : bad) {
        config::ModbusSlaves slaves;
        auto problem = config::loadModbusSlaves(writeModbusToml(b.text), slaves);
        ASSERT_TRUE(problem) << b.text;
        EXPECT_NE(problem->find(b.message), std::string::npos) << *problem;
    }
}

} // namespace
