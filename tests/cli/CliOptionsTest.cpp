// m350-sim's options: --print, --var, --param, --input, --tool, --unhomed, mdi, --max-sim-time,
// --trace, --sensor-timeout, and what they do to a run.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

TEST_F(CliTest, PrintReportsExactlyTheListedVariables) {
    write("ok.nc", "#100=2.5\nM30\n");
    ProcessResult r = sim({"run", "ok.nc", "--print", "1,100,1300"});
    json vars = output(r).value("vars", json());
    EXPECT_EQ(keysOf(vars), (std::set<std::string>{"1", "100", "1300"}));
    EXPECT_EQ(vars.value("1", json()), 0); // M350 locals start at 0
    EXPECT_EQ(vars.value("100", json()), 2.5);
    EXPECT_EQ(vars.value("1300", json()), 1); // param 800 of the default machine: tool 1

    ProcessResult none = sim({"run", "ok.nc"});
    EXPECT_EQ(output(none).value("vars", json()), json::object());
}

TEST_F(CliTest, VacantPrintsAsNull) {
    write("vacant.nc", "#101=3\n#102=#100\nM30\n");
    ProcessResult r = sim({"run", "vacant.nc", "--dialect", "fanuc", "--print", "100,101,102,0"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json vars = output(r).value("vars", json());
    EXPECT_TRUE(vars.value("100", json(1)).is_null()) << vars;
    EXPECT_EQ(vars.value("101", json()), 3);
    EXPECT_TRUE(vars.value("102", json(1)).is_null()) << vars;
    EXPECT_TRUE(vars.value("0", json(1)).is_null()) << vars;
}

TEST_F(CliTest, VarAndParamSetValuesBeforeTheRun) {
    write("copy.nc", "#101=#100\n#102=#561\nM30\n");
    ProcessResult r = sim({"run", "copy.nc", "--var", "100=7.5", "--param", "61=1234", "--param", "801=4",
                           "--print", "101,102,1301"});
    json j = output(r);
    EXPECT_EQ(j["vars"].value("101", json()), 7.5);
    EXPECT_EQ(j["vars"].value("102", json()), 1234);
    EXPECT_EQ(j["vars"].value("1301", json()), 4);
    EXPECT_EQ(keysOf(j.value("pockets", json::object())), (std::set<std::string>{"1", "2", "3", "4"}));
}

TEST_F(CliTest, MdiRunsTheLinesInOrder) {
    ProcessResult r =
        sim({"mdi", "#100=1", "#100=#100*10", "#100=#100+2", "G00 X5", "G00 X7", "--print", "100"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"].value("100", json()), 12); // (1 * 10) + 2; any other order gives another number
    EXPECT_EQ(j["work"].value("X", json()), 7);
}

TEST_F(CliTest, StartOptionsSetTheMachineUp) {
    write("probe.nc", "#100=#1526\nM30\n"); // #1526 = IN07
    json j = output(sim({"run", "probe.nc", "--tool", "3", "--unhomed", "--input", "IN07=1", "--print",
                         "100,1300,1515,1516,1517"}));
    EXPECT_EQ(j.value("tool", -1), 3);
    EXPECT_EQ(j["pockets"].value("3", -1), 0);
    EXPECT_EQ(j["vars"], (json{{"100", 1}, {"1300", 3}, {"1515", 0}, {"1516", 0}, {"1517", 0}}));
}

TEST_F(CliTest, MaxSimTimeStopsARunawayLoop) {
    write("loop.nc", "N1 G04 P1000\nGOTO1\n");
    ProcessResult r = sim({"run", "loop.nc", "--max-sim-time", "3"});
    EXPECT_EQ(r.exitStatus, kExitAlarm);
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit");
    EXPECT_DOUBLE_EQ(j.value("sim_time_s", 0.0), 3.0) << "the dwell under way stops at the limit";
}

TEST_F(CliTest, TraceWritesJsonLinesWithMoves) {
    write("moves.nc", "G00 X10 Y20\nG01 Z-5 F600\nT2\nG00 X0 Y0\nM30\n");
    ProcessResult r = sim({"run", "moves.nc", "--trace", "trace.jsonl"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json report = output(r);

    std::ifstream in(dir_ / "trace.jsonl");
    ASSERT_TRUE(in.good()) << "no trace file";
    std::string line;
    std::size_t moves = 0;
    double lastT = -1;
    json lastMove;
    std::vector<std::pair<int, int>> changes;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        json e;
        try {
            e = json::parse(line);
        } catch (const json::exception&) {
            ADD_FAILURE() << "trace line " << n << " is not JSON: " << line;
            continue;
        }
        ASSERT_TRUE(e.is_object()) << line;
        ASSERT_TRUE(e.contains("type") && e["type"].is_string()) << line;
        ASSERT_TRUE(e.contains("t") && e["t"].is_number()) << line;
        EXPECT_GE(e["t"].get<double>(), lastT) << "events in time order: " << line;
        lastT = e["t"].get<double>();
        if (e["type"] == "move") {
            ++moves;
            for (const char* end : {"from", "to"}) {
                ASSERT_TRUE(e.contains(end)) << line;
                EXPECT_EQ(keysOf(e[end]), (std::set<std::string>{"X", "Y", "Z", "A", "B"})) << line;
            }
            lastMove = e;
        }
        if (e["type"] == "toolchange") {
            changes.emplace_back(e.value("from", -1), e.value("to", -1));
        }
    }
    EXPECT_GT(n, 0);
    EXPECT_GE(moves, 3u);
    // what the spindle holds: T1 left in its pocket, then T2 clamped
    EXPECT_EQ(changes, (std::vector<std::pair<int, int>>{{1, 0}, {0, 2}}));
    ASSERT_TRUE(lastMove.is_object());
    for (const char* axis : {"X", "Y", "Z", "A", "B"}) {
        EXPECT_NEAR(lastMove["to"].value(axis, 1e300), report["machine"].value(axis, -1e300), 1e-9)
            << "the last move ends where the report says the machine is (" << axis << ")";
    }
}

// The seed README: the manual's damaged lines "must be rejected with a clear error at the right
// line"; docs/architecture.md: lint findings alarm "once such a line is reached". Running
// `G53 X[#1330+#1300-1]` must not move the spindle to pocket X + tool number - 1.
TEST_F(CliTest, RunRejectsTheManualsDamagedPocketMove) {
    write("pocket.nc", "G53 Z#1306 F#1312\nG53 X[#1330+#1300-1] F#1311\nM30\n");
    ProcessResult r = sim({"run", "pocket.nc", "--tool", "2"});
    json j = output(r);
    EXPECT_NE(j.value("status", ""), "ok") << "machine X ended at " << j["machine"].value("X", json());
    EXPECT_NE(r.exitStatus, kExitOk);
    if (j.value("alarm", json()).is_object()) {
        EXPECT_EQ(j["alarm"].value("line", 0), 2) << j["alarm"];
    }
}


TEST_F(CliTest, ParameterOutsideThePanelRangeIsUsedWithAWarning) {
    fs::path program = write("param.nc", kEndingProgram);
    ProcessResult r = sim({"run", program.string(), "--param", "801=25", "--print", "1301"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("warning: --param 801=25: parameter 801 (Total number of tools) must be a whole number "
                         "from 0 to 20, not 25"),
              std::string::npos)
        << r.err;
    EXPECT_DOUBLE_EQ(json::parse(r.out)["vars"]["1301"].get<double>(), 25.0);
}

} // namespace m350::clitest

namespace m350::clitest {

TEST_F(CliTest, SensorTimeoutStopsAWaitForAStuckInput) {
    // T2 on the default machine: O20000 waits for IN11 (tool released), held at 0
    ProcessResult r = sim({"mdi", "T2", "--input", "IN11=0", "--sensor-timeout", "2"});
    EXPECT_EQ(r.exitStatus, kExitAlarm);
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "sensor_timeout");
    EXPECT_EQ(j["alarm"].value("message", ""), "IN11 (tool released) never became 1: waited 2.0 s at slib-g.nc:46");
    EXPECT_EQ(sim({"mdi", "T2", "--sensor-timeout", "0"}).exitStatus, kExitUsage);
}

} // namespace m350::clitest
