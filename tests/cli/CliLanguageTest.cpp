// The Custom Macro B statements real shops write, run through m350-sim as a user runs them: bare
// DO loops, external output (POPEN/DPRNT/BPRNT/PCLOS) into a file, look-ahead G codes in the
// trace, and the M350's Modbus statements against the machine folder's slave table.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

TEST_F(CliTest, BareDoLoopIsLeftByGoto) {
    write("loop.nc", "#1=0\nDO1\n#1=#1+1\nIF [#1 GE 7] GOTO9\nEND1\nN9 M30\n");
    for (const char* dialect : {"m350", "fanuc"}) {
        ProcessResult r = sim({"run", "loop.nc", "--dialect", dialect, "--print", "1"});
        EXPECT_EQ(r.exitStatus, kExitOk) << dialect << ": " << r.err;
        json j = output(r);
        EXPECT_EQ(j["vars"].value("1", json()), 7) << dialect << ": " << r.out;
    }
}

TEST_F(CliTest, BareDoLoopThatNeverEndsIsStoppedByTheTimeLimit) {
    write("forever.nc", "#1=0\nDO1\n#1=#1+1\nEND1\nM30\n");
    ProcessResult r = sim({"run", "forever.nc", "--max-sim-time", "0.2"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit") << r.out;
    EXPECT_EQ(j["alarm"].value("file", ""), "forever.nc");
    EXPECT_NE(r.err.find("forever.nc:"), std::string::npos) << r.err;
}

TEST_F(CliTest, CheckReportsABareDoWithoutEnd) {
    write("open.nc", "#1=0\nN5 DO2\n#1=#1+1\nM30\n");
    ProcessResult r = sim({"check", "open.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find("open.nc:2:4: DO2 has no END2"), std::string::npos) << r.err;
}

TEST_F(CliTest, LookAheadCodesAreInTheTraceOfAFanucRun) {
    write("hpcc.nc", "G90 G1 X10 F1000\nG05.1 Q1 R3\nG1 X20\nG05.1 Q0\nM30\n");
    ProcessResult r = sim({"run", "hpcc.nc", "--dialect", "fanuc", "--trace", "trace.jsonl"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    std::ifstream in(dir_ / "trace.jsonl");
    std::vector<std::string> codes;
    int moves = 0;
    for (std::string line; std::getline(in, line);) {
        json event = json::parse(line);
        if (event["type"] == "lookahead") {
            codes.push_back(event["code"].get<std::string>() + " " + event["file"].get<std::string>() + ":" +
                            std::to_string(event["line"].get<int>()));
        }
        moves += event["type"] == "move" ? 1 : 0;
    }
    EXPECT_EQ(codes, (std::vector<std::string>{"G05.1 Q1 R3 hpcc.nc:2", "G05.1 Q0 hpcc.nc:4"}));
    EXPECT_EQ(moves, 2);
}

TEST_F(CliTest, LookAheadCodesAreUnknownGCodesOnTheM350) {
    write("hpcc.nc", "G90\nG05.1 Q1\nM30\n");
    ProcessResult r = sim({"run", "hpcc.nc"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("hpcc.nc:2:1: alarm: G5.1: not a G code this machine knows"), std::string::npos) << r.err;
}

namespace {

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const char* const kReportProgram = "#2=128.47398\n#5=-91.2\nPOPEN\nDPRNT[X#2[53]*Y#5[53]]\n"
                                   "DPRNT[*PART*OK]\nPCLOS\nM30\n";

} // namespace

TEST_F(CliTest, DprntOutputIsWrittenBesideTheProgram) {
    write("jobs/report.nc", kReportProgram);
    ProcessResult r = sim({"run", "jobs/report.nc", "--dialect", "fanuc", "--trace", "trace.jsonl"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(output(r).value("status", ""), "ok");
    EXPECT_EQ(readFile(dir_ / "jobs" / "dprnt.txt"), "X   128.474 Y-   91.200\n PART OK\n");
    EXPECT_NE(r.err.find("written to jobs/dprnt.txt"), std::string::npos) << r.err;
    std::ifstream trace(dir_ / "trace.jsonl");
    std::vector<std::string> sent;
    for (std::string line; std::getline(trace, line);) {
        json event = json::parse(line);
        if (event["type"] == "output") {
            sent.push_back(event["statement"].get<std::string>() + ":" + event.value("text", "") + "@" +
                           std::to_string(event["line"].get<int>()));
        }
    }
    EXPECT_EQ(sent, (std::vector<std::string>{"POPEN:@3", "DPRNT:X   128.474 Y-   91.200@4", "DPRNT: PART OK@5",
                                              "PCLOS:@6"}));
}

TEST_F(CliTest, DprntOptionNamesTheFile) {
    write("report.nc", kReportProgram);
    ProcessResult r = sim({"run", "report.nc", "--dialect", "fanuc", "--dprnt", "measured.txt"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(readFile(dir_ / "measured.txt"), "X   128.474 Y-   91.200\n PART OK\n");
    EXPECT_FALSE(fs::exists(dir_ / "dprnt.txt"));
}

TEST_F(CliTest, DprntFileThatCannotBeWrittenIsAnError) {
    write("report.nc", kReportProgram);
    ProcessResult r = sim({"run", "report.nc", "--dialect", "fanuc", "--dprnt", "no/such/folder/out.txt"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_NE(r.err.find("cannot write the external output"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no/such/folder/out.txt"), std::string::npos) << r.err;
}

TEST_F(CliTest, MdiDprntGoesToTheCurrentFolder) {
    ProcessResult r = sim({"mdi", "POPEN", "DPRNT[MDI*#1[20]]", "PCLOS", "--dialect", "fanuc", "--var", "1=7"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(readFile(dir_ / "dprnt.txt"), "MDI   7\n");
}

TEST_F(CliTest, DprntWithoutPopenIsAnAlarmAndWritesNoFile) {
    write("report.nc", "#1=2\nN10 DPRNT[A#1[10]]\nM30\n");
    ProcessResult r = sim({"run", "report.nc", "--dialect", "fanuc"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_EQ(output(r)["alarm"].value("code", ""), "device_error");
    EXPECT_NE(r.err.find("report.nc:2:5: alarm: DPRNT without POPEN"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "dprnt.txt"));
}

namespace {

// A copy of the bundled M350 with a Modbus slave table in its folder.
fs::path machineWithModbus(const fs::path& into, const std::string& modbusToml) {
    fs::create_directories(into);
    fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", into,
             fs::copy_options::overwrite_existing | fs::copy_options::recursive);
    std::ofstream(into / "modbus.toml", std::ios::binary) << modbusToml;
    return into;
}

} // namespace

// MSETDATA then MGETDATA in the firmware's six-argument form against the folder's slave: the
// bytes come back, and the trace has the frames a PC slave would log.
TEST_F(CliTest, ModbusStatementsRunAgainstTheMachineFoldersSlaves) {
    fs::path machine = machineWithModbus(dir_ / "machine", "[slave.1.holding]\n0 = 0\n1 = 0\n");
    write("vfd.nc", "#200=11\n#201=22\n#202=33\n#203=44\nMSETDATA[200,1,0,4,16,300]\n"
                    "MGETDATA[250,1,0,4,3,301]\nM30\n");
    ProcessResult r = sim({"run", "vfd.nc", "--config", machine.string(), "--param", "279=1", "--print",
                           "250,251,252,253,300,301", "--trace", "trace.jsonl"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    const int expected[] = {11, 22, 33, 44, 0, 0};
    const char* names[] = {"250", "251", "252", "253", "300", "301"};
    for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(j["vars"].value(names[k], json()), expected[k]) << names[k] << ": " << r.out;
    }
    std::ifstream trace(dir_ / "trace.jsonl");
    std::vector<std::string> transfers;
    for (std::string line; std::getline(trace, line);) {
        json event = json::parse(line);
        if (event["type"] == "modbus") {
            transfers.push_back(event["statement"].get<std::string>() + " @" + std::to_string(event["line"].get<int>()) +
                                ": " + event["request"].get<std::string>() + " -> " + event["answer"].get<std::string>());
        }
    }
    // the CRCs: CRC-16/MODBUS of each frame's other bytes, low byte first
    EXPECT_EQ(transfers, (std::vector<std::string>{
                             "MSETDATA @5: 01 10 00 00 00 02 04 16 0B 2C 21 5A FD -> 01 10 00 00 00 02 41 C8",
                             "MGETDATA @6: 01 03 00 00 00 02 C4 0B -> 01 03 04 16 0B 2C 21 53 61",
                         }));
    // the run works in memory: the folder's table is as it was
    std::ifstream in(machine / "modbus.toml");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
              "[slave.1.holding]\n0 = 0\n1 = 0\n");
}

TEST_F(CliTest, ModbusNeedsParameter279) {
    fs::path machine = machineWithModbus(dir_ / "machine", "[slave.1.holding]\n0 = 0\n");
    write("vfd.nc", "G0 X1\nMSETDATA[200,1,0,2,16,300]\nM30\n");
    ProcessResult r = sim({"run", "vfd.nc", "--config", machine.string()});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("vfd.nc:2:1: alarm: MSETDATA: Modbus RTU is off (parameter 279 = 0)"), std::string::npos)
        << r.err;
}

// On the controller an MGETDATA to a slave that does not answer hangs it; the run stops after the
// controller's 16 s with an alarm naming the slave.
TEST_F(CliTest, AnUnansweredMgetdataAlarmsNamingTheSlave) {
    fs::path machine = machineWithModbus(dir_ / "machine", "[slave.1.holding]\n0 = 0\n");
    write("vfd.nc", "MGETDATA[200,3,0,2,3,300]\nM30\n");
    ProcessResult r = sim({"run", "vfd.nc", "--config", machine.string(), "--param", "279=1"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "device_error");
    EXPECT_NE(r.err.find("vfd.nc:1:1: alarm: MGETDATA: Modbus slave 3 did not answer within 16 s; on the controller "
                         "this hangs MGETDATA until a reboot (modbus.toml declares no [slave.3])"),
              std::string::npos)
        << r.err;
}

// The old three-argument form, arguments out of range and unknown functions: `check` and `run`
// refuse them at their place.
TEST_F(CliTest, CheckAndRunRefuseWrongModbusArguments) {
    fs::path machine = machineWithModbus(dir_ / "machine", "[slave.1.holding]\n0 = 0\n");
    write("bad.nc", "MSETDATA[1,8192,3000]\nMGETDATA[10,1,0,4,3,300]\nMGETDATA[498,1,0,4,3,300]\n"
                    "MSETDATA[200,1,0,4,3,300]\nMGETDATA[200,1,0,4,3]\nM30\n");
    const char* findings[] = {
        ("bad.nc:1:1: MSETDATA[slave, register, value] was this simulator's own form, not the firmware's: the M350 "
         "takes six arguments, MSETDATA[first variable, slave, register, bytes, function, exception variable]"),
        "bad.nc:2:10: MGETDATA: the first variable (X1) must be a whole number from 50 to 499, not 10",
        "bad.nc:3:18: MGETDATA: X4 = 4 bytes from #498 reach #501: the Modbus statements' variables end at #499",
        "bad.nc:4:20: MSETDATA: the Modbus function (X5) of MSETDATA is 16 (write registers) or 15 (write coils), not 3",
        "bad.nc:5:1: MGETDATA takes 6 arguments, not 5",
    };
    ProcessResult check = sim({"check", "bad.nc", "--config", machine.string()});
    EXPECT_EQ(check.exitStatus, kExitError);
    ProcessResult run = sim({"run", "bad.nc", "--config", machine.string(), "--param", "279=1"});
    EXPECT_EQ(run.exitStatus, kExitError) << run.err;
    for (const char* finding : findings) {
        EXPECT_NE(check.err.find(finding), std::string::npos) << finding << "\n" << check.err;
        EXPECT_NE(run.err.find(finding), std::string::npos) << finding << "\n" << run.err;
    }
}

TEST_F(CliTest, ABrokenModbusTableIsAConfigError) {
    fs::path machine = machineWithModbus(dir_ / "machine", "[slave.1.holding]\n8192 = 99999\n");
    write("vfd.nc", "M30\n");
    ProcessResult r = sim({"run", "vfd.nc", "--config", machine.string()});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_EQ(output(r).value("status", ""), "error");
    EXPECT_NE(r.err.find("modbus.toml: line 2: slave 1 holding '8192'"), std::string::npos) << r.err;
}

TEST_F(CliTest, CheckFlagsTheModbusConversions) {
    write("conv.nc", "#1=0\nMBYTE2DATA[#1,#2]\nM30\n");
    ProcessResult r = sim({"check", "conv.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find("conv.nc:2:1: MBYTE2DATA is not simulated"), std::string::npos) << r.err;
}

} // namespace m350::clitest
