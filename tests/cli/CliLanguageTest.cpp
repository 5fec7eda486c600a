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

} // namespace m350::clitest
