// The M350's Modbus statements in the firmware's six-argument form, against simulated slaves:
// MSETDATA[X1,X2,X3,X4,X5,X6] sends the bytes of #X1.. to slave X2 from register X3, X4 bytes by
// function X5, and puts the slave's exception code in #X6; MGETDATA[...] reads them into #X1..,
// with parameter 279 (Modbus RTU) on. modbus.toml states the slaves; MBYTE2DATA and MDATA2BYTE
// are flagged, not guessed.
#include "ParseSupport.h"
#include "RunProgram.h"

#include "core/config/ModbusSlaves.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using namespace m350;
using gcode::Dialect;
using gcode::support::listDiagnostics;
using test::lines;

// An M350 with Modbus on; slave 1 holds registers 0-1 (0) and 10-11 (the owners' test pattern:
// 66 << 8 | 55, 88 << 8 | 77), slave 7 coils 0-15 and discrete inputs 0-7.
config::MachineConfig modbusMachine(bool enabled = true) {
    config::MachineConfig config = test::m350Machine();
    config.parameters.set(param::kModbusRtu, enabled ? 1 : 0);
    devices::ModbusMemory& one = config.modbus.slaves[1];
    one.holding = {{0, 0}, {1, 0}, {10, 66 << 8 | 55}, {11, 88 << 8 | 77}};
    one.input = {{0, 0x0102}};
    devices::ModbusMemory& seven = config.modbus.slaves[7];
    for (int a = 0; a < 16; ++a) {
        seven.coils[a] = false;
    }
    seven.discrete = {{0, true}, {1, false}, {2, true}, {3, false}, {4, false}, {5, false}, {6, false}, {7, true}};
    return config;
}

TEST(ModbusStatements, WriteThenReadBackThroughTheSlave) {
    auto run = test::runProgram(modbusMachine(), lines({
        "#300 = -1",
        "#200 = 11",
        "#201 = 22",
        "#202 = 33",
        "#203 = 44",
        "MSETDATA[200,1,0,4,16,300]",
        "#301 = #300",
        "MGETDATA[250,1,0,4,3,302]",     // back into #250-#253
        "MGETDATA[260,1,10,4,3,303]",    // the owners' pattern: 55 66 77 88
        "MGETDATA[270,1,0,2,4,304]",     // input register 0 = 0x0102
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(301), 0); // exception code 0: done
    for (int k = 0; k < 4; ++k) {
        EXPECT_DOUBLE_EQ(run.number(250 + k), 11 * (k + 1)) << k;
    }
    EXPECT_DOUBLE_EQ(run.number(260), 55);
    EXPECT_DOUBLE_EQ(run.number(261), 66);
    EXPECT_DOUBLE_EQ(run.number(262), 77);
    EXPECT_DOUBLE_EQ(run.number(263), 88);
    EXPECT_DOUBLE_EQ(run.number(270), 2);
    EXPECT_DOUBLE_EQ(run.number(271), 1);
    for (int x6 = 302; x6 <= 304; ++x6) {
        EXPECT_DOUBLE_EQ(run.number(x6), 0) << x6;
    }
}

TEST(ModbusStatements, ArgumentsMayBeExpressions) {
    auto run = test::runProgram(modbusMachine(), lines({
        "#100 = 200",
        "#200 = 7",
        "#201 = 8",
        "MSETDATA[#100, 1, 1-1, 2, 8*2, #100+100]",
        "MGETDATA[#100+10, 1, 0, 2, 3, 301]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(210), 7);
    EXPECT_DOUBLE_EQ(run.number(211), 8);
    EXPECT_DOUBLE_EQ(run.number(300), 0);
}

TEST(ModbusStatements, CoilsAndDiscreteInputsMoveEightABytes) {
    auto run = test::runProgram(modbusMachine(), lines({
        "#100 = 5",
        "#101 = 128",
        "MSETDATA[100,7,0,2,15,300]",
        "MGETDATA[110,7,0,2,1,301]",
        "MGETDATA[120,7,0,1,2,302]",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(110), 5);
    EXPECT_DOUBLE_EQ(run.number(111), 128);
    EXPECT_DOUBLE_EQ(run.number(120), 0x85); // inputs 0, 2 and 7
    EXPECT_DOUBLE_EQ(run.number(300) + run.number(301) + run.number(302), 0);
}

// The slave's exception comes back in #X6 and the program goes on: it is the program's to check.
TEST(ModbusStatements, AnExceptionGoesIntoX6AndTheRunGoesOn) {
    auto run = test::runProgram(modbusMachine(), lines({
        "#250 = 9",
        "MGETDATA[250,1,2,2,3,300]",    // register 2: exception 02
        "MGETDATA[260,7,0,2,4,301]",    // slave 7 has no input registers: exception 01
        "MSETDATA[240,1,0,252,16,302]", // 126 registers: exception 03
        "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(300), 2);
    EXPECT_DOUBLE_EQ(run.number(301), 1);
    EXPECT_DOUBLE_EQ(run.number(302), 3);
    EXPECT_DOUBLE_EQ(run.number(250), 9); // untouched by the refused read
}

TEST(ModbusStatements, ASilentSlaveAlarmsAfterTheTimeoutNamingIt) {
    auto run = test::runProgram(modbusMachine(), lines({"G4 P1000", "MGETDATA[200,5,0,2,3,300]", "M30"}));
    ASSERT_TRUE(run.report.alarm);
    const Alarm& a = *run.report.alarm;
    EXPECT_EQ(a.code, AlarmCode::DeviceError);
    EXPECT_EQ(a.line, 2u);
    EXPECT_EQ(a.column, 1u);
    EXPECT_EQ(a.message, "MGETDATA: Modbus slave 5 did not answer within 16 s; on the controller this hangs MGETDATA "
                         "until a reboot (modbus.toml declares no [slave.5])");
    EXPECT_EQ(a.messageId, "modbus_read_no_answer");
    EXPECT_EQ(a.messageArguments, (std::vector<std::string>{"5", "16"}));
    EXPECT_NEAR(run.report.simTime, 17.0, 0.01); // the dwell, then the 16 s wait

    auto write = test::runProgram(modbusMachine(), lines({"#200 = 1", "MSETDATA[200,9,0,1,16,300]", "M30"}));
    ASSERT_TRUE(write.report.alarm);
    EXPECT_EQ(write.report.alarm->messageId, "modbus_write_no_answer");
    EXPECT_EQ(write.report.alarm->message,
              "MSETDATA: Modbus slave 9 did not answer within 16 s (modbus.toml declares no [slave.9])");
}

struct Refusal {
    const char* line;
    AlarmCode code;
    std::uint32_t column;
    const char* message;
};

// Arguments that are expressions are checked when the line runs, with the words of the parser.
TEST(ModbusStatements, RunTimeRefusalsAlarmAtTheArgument) {
    const Refusal refusals[] = {
        {"MSETDATA[#1,1,0,2,16,300]", AlarmCode::InvalidArgument, 10,
         "MSETDATA: the first variable (X1) must be a whole number from 50 to 499, not 10"},
        {"MSETDATA[#2,1,0,#3,16,300]", AlarmCode::InvalidArgument, 17,
         "MSETDATA: X4 = 10 bytes from #495 reach #504: the Modbus statements' variables end at #499"},
        {"MGETDATA[200,#1-10,0,2,3,300]", AlarmCode::InvalidArgument, 14,
         "MGETDATA: the slave (X2) must be a whole number from 1 to 247, not 0"},
        {"MGETDATA[200,1,0,2,#3+6,300]", AlarmCode::InvalidArgument, 20,
         "MGETDATA: the Modbus function (X5) of MGETDATA is 3 (read holding registers)"},
        {"MGETDATA[200,1,0,2,3,#1*100]", AlarmCode::InvalidArgument, 22,
         "MGETDATA: the exception variable (X6) must be a whole number from 50 to 499, not 1000"},
        {"MSETDATA[#4,1,0,2,16,300]", AlarmCode::InvalidArgument, 10,
         "MSETDATA sends #201 = 300: each variable carries one byte, a whole number from 0 to 255"},
        {"MSETDATA[300,1,0,2,16,300]", AlarmCode::InvalidArgument, 10,
         "MSETDATA sends #300 = 2.5: each variable carries one byte"},
    };
    for (const Refusal& r : refusals) {
        auto run = test::runProgram(modbusMachine(), lines({"#1 = 10", "#2 = 495", "#3 = 10", "#4 = 200", "#201 = 300",
                                                            "#300 = 2.5", r.line, "M30"}));
        ASSERT_TRUE(run.report.alarm) << r.line;
        EXPECT_EQ(run.report.alarm->code, r.code) << r.line << ": " << run.alarmText();
        EXPECT_EQ(run.report.alarm->line, 7u) << r.line;
        EXPECT_EQ(run.report.alarm->column, r.column) << r.line << ": " << run.alarmText();
        EXPECT_EQ(run.report.alarm->message.rfind(r.message, 0), 0u) << run.report.alarm->message;
    }
}

TEST(ModbusStatements, ParameterTwo79OffMeansNoModbus) {
    auto run = test::runProgram(modbusMachine(false), lines({"N4 MSETDATA[200,1,0,2,16,300]", "M30"}));
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
        {"MSETDATA[1, 8192, 3000]", &Dialect::m350(), 1,
         "MSETDATA[slave, register, value] was this simulator's own form, not the firmware's: the M350 takes six "
         "arguments, MSETDATA[first variable, slave, register, bytes, function, exception variable], e.g. "
         "MSETDATA[200,1,0,4,16,300] writes #200-#203 into registers 0-1 of slave 1"},
        {"MGETDATA[1, 8193, #100]", &Dialect::m350(), 1,
         "MGETDATA[slave, register, #variable] was this simulator's own form, not the firmware's: the M350 takes six "
         "arguments"},
        {"MSETDATA[200,1,0,4,16]", &Dialect::m350(), 1,
         "MSETDATA takes 6 arguments, not 5: MSETDATA[first variable, slave, register, bytes, function, exception "
         "variable]"},
        {"MSETDATA[10,1,0,4,16,300]", &Dialect::m350(), 10,
         "MSETDATA: the first variable (X1) must be a whole number from 50 to 499, not 10: the Modbus statements "
         "move #50-#499, one byte each, and X1 is the number (200), not #200"},
        {"MSETDATA[498,1,0,4,16,300]", &Dialect::m350(), 18,
         "MSETDATA: X4 = 4 bytes from #498 reach #501: the Modbus statements' variables end at #499"},
        {"MSETDATA[200,1,0,4,3,300]", &Dialect::m350(), 20,
         "MSETDATA: the Modbus function (X5) of MSETDATA is 16 (write registers) or 15 (write coils), not 3"},
        {"MGETDATA[200,1,0,4,16,300]", &Dialect::m350(), 20,
         "MGETDATA: the Modbus function (X5) of MGETDATA is 3 (read holding registers), 4 (read input registers), "
         "1 (read coils) or 2 (read discrete inputs), not 16"},
        {"MGETDATA[200,0,0,4,3,300]", &Dialect::m350(), 14, "MGETDATA: the slave (X2) must be a whole number from 1 to 247"},
        {"MGETDATA[200,1,-1,4,3,300]", &Dialect::m350(), 16,
         "MGETDATA: the first register (X3) must be a whole number from 0 to 65535, not -1"},
        {"MGETDATA[200,1,0,0,3,300]", &Dialect::m350(), 18,
         "MGETDATA: the length (X4) counts bytes: it must be a whole number from 1 to 450, not 0"},
        {"MGETDATA[200,1,0,2.5,3,300]", &Dialect::m350(), 18, "MGETDATA: the length (X4) counts bytes"},
        {"MGETDATA[200,1,0,2,3,500]", &Dialect::m350(), 22,
         "MGETDATA: the exception variable (X6) must be a whole number from 50 to 499, not 500"},
        {"MGETDATA 1", &Dialect::m350(), 10,
         "MGETDATA must be followed by [...]: MGETDATA[first variable, slave, register, bytes, function, exception "
         "variable]"},
        {"MSETDATA[1, 2, 3", &Dialect::m350(), 17, "missing ']' to close MSETDATA[ at column 9"},
        {"MSETDATA[200,1,0,4,16,300] X1", &Dialect::m350(), 28, "unexpected 'X' after MSETDATA[...]"},
        {"MSETDATA[200,1,0,4,16,300]", &Dialect::fanuc(), 1,
         "MSETDATA is an M350 Modbus statement: the fanuc dialect has none"},
        {"msetdata[200,1,0,4,16,300]", &Dialect::m350(), 1, "keywords are upper case in the m350 dialect: write MSETDATA"},
    };
    for (const Bad& b : bad) {
        gcode::support::expectOneDiagnostic(gcode::support::parse(b.line, *b.dialect), gcode::DiagnosticKind::Syntax,
                                            1, b.column, b.message, b.line);
    }
}

// #200 as X1 is legal (the number #200 holds) but rarely meant: a note, and the line runs as written.
TEST(ModbusStatements, AVariableReferenceAsX1OrX6IsNoted) {
    auto p = gcode::support::parse("MSETDATA[#200,1,0,2,16,#300]", Dialect::m350());
    ASSERT_EQ(p.diagnostics.size(), 2u) << listDiagnostics(p.diagnostics);
    EXPECT_EQ(p.diagnostics[0].severity, gcode::Severity::Warning);
    EXPECT_EQ(p.diagnostics[0].column, 10u);
    EXPECT_EQ(p.diagnostics[0].message,
              "MSETDATA: X1 is a variable's number: #200 stands for the number #200 holds; write 200 to mean #200");
    EXPECT_EQ(p.diagnostics[1].column, 24u);
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
    ASSERT_TRUE(c.loadFile(test::writeTempFile(lines({"MSETDATA[200,1,0,2,16,300]", "G0 X1", "G0 X2", "M30"}))));
    Message why;
    EXPECT_FALSE(c.breakRun().startAtLine(3, &why));
    EXPECT_NE(why.english().find("MSETDATA talks to Modbus slave 1"), std::string::npos) << why;
    EXPECT_EQ(why.english(), "MSETDATA talks to Modbus slave 1 at " + why.arguments[1] + ", before the start line: a scan cannot");
    EXPECT_EQ(why.in(MessageLanguage::Chinese), "起始行之前的" + why.arguments[1] + "：MSETDATA与Modbus从站1通信，扫描无法执行");
}

// The trace has both frames of each transfer, as a PC slave would log them.
TEST(ModbusStatements, TheTraceHasTheFrames) {
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    auto run = test::runProgram(modbusMachine(),
                                lines({"#200 = 11", "#201 = 22", "#202 = 33", "#203 = 44", "MSETDATA[200,1,0,4,16,300]",
                                       "MGETDATA[200,6,0,2,3,300]"}),
                                settings);
    ASSERT_TRUE(run.report.alarm);
    std::vector<nlohmann::json> transfers;
    std::istringstream in(trace.str());
    for (std::string line; std::getline(in, line);) {
        auto event = nlohmann::json::parse(line);
        if (event["type"] == "modbus") {
            transfers.push_back(event);
        }
    }
    ASSERT_EQ(transfers.size(), 2u) << trace.str();
    EXPECT_EQ(transfers[0]["statement"], "MSETDATA");
    EXPECT_EQ(transfers[0]["function"], 16);
    EXPECT_EQ(transfers[0]["request"].get<std::string>().rfind("01 10 00 00 00 02 04 16 0B 2C 21 ", 0), 0u);
    EXPECT_EQ(transfers[0]["answer"].get<std::string>().rfind("01 10 00 00 00 02 ", 0), 0u);
    EXPECT_EQ(transfers[0]["exception"], 0);
    EXPECT_EQ(transfers[0]["line"], 5);
    EXPECT_EQ(transfers[1]["slave"], 6);
    EXPECT_TRUE(transfers[1]["answer"].is_null());
    EXPECT_FALSE(transfers[1].contains("exception"));
}

// ---------------------------------------------------------------- modbus.toml

std::string writeModbusToml(const std::string& text) {
    std::string path = testing::TempDir() + "m350_modbus_" +
                       testing::UnitTest::GetInstance()->current_test_info()->name() + ".toml";
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(ModbusSlavesFile, ReadsSlavesAndTheirTables) {
    config::ModbusSlaves slaves;
    auto problem = config::loadModbusSlaves(writeModbusToml("[slave.1.holding]\n8192 = 0\n8193 = -1\n\n"
                                                            "[slave.1.input]\n0 = 258\n"
                                                            "[slave.1.coils]\n0 = 1\n1 = false\n"
                                                            "[slave.1.discrete]\n5 = true\n"
                                                            "[slave.17]\nholding = { 0 = 42 }\n"),
                                            slaves);
    ASSERT_FALSE(problem) << *problem;
    EXPECT_EQ(slaves.slaves.size(), 2u);
    const devices::ModbusMemory& one = slaves.slaves[1];
    EXPECT_EQ(one.holding.at(8192), 0);
    EXPECT_EQ(one.holding.at(8193), 65535);
    EXPECT_EQ(one.input.at(0), 258);
    EXPECT_TRUE(one.coils.at(0));
    EXPECT_FALSE(one.coils.at(1));
    EXPECT_TRUE(one.discrete.at(5));
    EXPECT_EQ(slaves.slaves[17].holding.at(0), 42);
}

TEST(ModbusSlavesFile, AMissingFileIsNoSlave) {
    config::ModbusSlaves slaves;
    EXPECT_FALSE(config::loadModbusSlaves(testing::TempDir() + "m350_no_such_modbus.toml", slaves));
    EXPECT_TRUE(slaves.slaves.empty());
}

TEST(ModbusSlavesFile, BadEntriesNameTheirLine) {
    struct Bad {
        const char* text;
        const char* message;
    };
    const Bad bad[] = {
        {"[slave.1.holding]\n8192 = 70000\n", "line 2: slave 1 holding '8192': addresses are 0-65535"},
        {"[slave.1.holding]\n70000 = 1\n", "line 2: slave 1 holding '70000'"},
        {"[slave.1.input]\n5 = 1.5\n", "line 2: slave 1 input '5'"},
        {"[slave.1.coils]\n5 = 2\n", "line 2: slave 1 coils '5': addresses are 0-65535 and values 0 or 1"},
        {"[slave.300.holding]\n5 = 1\n", "[slave.300] must be a slave address 1-247"},
        {"[slave.1]\nregisters = 5\n", "line 2: slave 1: 'registers' is none of its tables: holding, input"},
        {"[slave.1.holding\n", "1:"},
    };
    for (const Bad& b : bad) {
        config::ModbusSlaves slaves;
        auto problem = config::loadModbusSlaves(writeModbusToml(b.text), slaves);
        ASSERT_TRUE(problem) << b.text;
        EXPECT_NE(problem->english().find(b.message), std::string::npos) << *problem;
    }
}

} // namespace
