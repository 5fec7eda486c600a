// Issue 24: an owner imports the system disk of a real M350 (a dual-Y gantry, soft limits on, the
// factory's M30 handler running M5M9M11) and does the first things an owner does: Go Home, a
// program to M30, the K keys. Each runs to its end with no alarm, and `check` passes the files.
#include "tests/cli/CliFixture.h"
#include "tests/support/ControllerBackupWriter.h"

#include <gtest/gtest.h>

namespace m350::clitest {

using m350::testing::ControllerBackupWriter;

namespace {

// A code point of U+0080-U+00FF after another: GBK text that was read as Latin-1 (×Ô¶¨Òå...).
bool looksLikeLatin1Mojibake(const std::string& utf8) {
    bool previous = false;
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto byte = static_cast<unsigned char>(utf8[i]);
        const bool latin1 = (byte == 0xC2 || byte == 0xC3) && i + 1 < utf8.size();
        if (latin1 && previous) {
            return true;
        }
        previous = latin1;
        if (latin1) {
            ++i;
        }
    }
    return false;
}

} // namespace

class CliOwnerBackupTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        backup_ = ControllerBackupWriter::dualYGantry();
        backup_.writeTo(dir_ / "SYSDISK");
        imported_ = sim({"import", "SYSDISK", "--into", "machine"});
        ASSERT_EQ(imported_.exitStatus, kExitOk) << imported_.err;
    }

    // Runs m350-sim on the imported machine; the run must end without an alarm.
    json runOk(std::vector<std::string> args) {
        for (const char* option : {"--config", "machine"}) {
            args.emplace_back(option);
        }
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitOk) << r.out << "\n" << r.err;
        json j = output(r);
        EXPECT_EQ(j.value("status", ""), "ok") << j.value("alarm", json());
        return j;
    }

    ControllerBackupWriter backup_;
    ProcessResult imported_;
};

TEST_F(CliOwnerBackupTest, CheckPassesEveryFileTheOwnerRuns) {
    const json result = output(imported_);
    EXPECT_TRUE(result["diagnostics"].empty()) << result["diagnostics"];
    write("program.nc", "G90 G0 X10 Y10\nG1 Z-1 F500\nM30\n");
    for (const char* file : {"program.nc", "machine/fndzero.nc", "machine/key-2.nc", "machine/key-3.nc"}) {
        ProcessResult r = sim({"check", file, "--config", "machine"});
        EXPECT_EQ(r.exitStatus, kExitOk) << file << ": " << r.out << r.err;
    }
}

// Go Home runs the owner's fndzero.nc: Z, X, Y by the library's O501, whose G31 searches 10 m
// toward each switch, far beyond the soft limits the machine has on (params 155, 161-170): an axis
// being homed has no trusted position, so they do not stop the search. Then A takes Y's position.
TEST_F(CliOwnerBackupTest, GoHomeSearchesPastTheSoftLimitsAndLeavesFourAxesHomed) {
    json j = runOk({"hook", "fndzero", "--unhomed", "--print", "1515,1516,1517,1518,655,663,668"});
    EXPECT_EQ(j["vars"]["655"], 1); // soft limits on
    for (const char* flag : {"1515", "1516", "1517", "1518"}) {
        EXPECT_EQ(j["vars"][flag], 1) << flag;
    }
    EXPECT_DOUBLE_EQ(j["machine"]["X"].get<double>(), backup_.setting[122]);
    EXPECT_DOUBLE_EQ(j["machine"]["Y"].get<double>(), backup_.setting[123]);
    EXPECT_DOUBLE_EQ(j["machine"]["Z"].get<double>(), backup_.setting[124]);
    EXPECT_DOUBLE_EQ(j["machine"]["A"].get<double>(), j["machine"]["Y"].get<double>());

    // homing again on a homed machine: O501 (M98 P501) starts by forgetting the axis's position
    json again = runOk({"hook", "fndzero", "--print", "1515,1516,1517,1518"});
    for (const char* flag : {"1515", "1516", "1517", "1518"}) {
        EXPECT_EQ(again["vars"][flag], 1) << flag;
    }
    EXPECT_DOUBLE_EQ(again["machine"]["Z"].get<double>(), backup_.setting[124]);
}

// Param 220 asks for homing first; the program ends at M30, which the library's O10030 handles:
// M5 M9 and the firmware's own M11 (lubrication off, param 94's 2 s), the counters.
TEST_F(CliOwnerBackupTest, AProgramRunsToM30ThroughTheFactoryM30Handler) {
    write("program.nc", "G90 G0 X10 Y10\nG1 Z-1 F500\nM30\n");
    json j = runOk({"run", "program.nc", "--unhomed", "--home", "--print", "701,702,1506"});
    EXPECT_EQ(j["vars"]["701"], backup_.setting[201] + 1);
    EXPECT_EQ(j["vars"]["702"], backup_.setting[202] + 1);
    EXPECT_EQ(j["vars"]["1506"], 30);
    EXPECT_DOUBLE_EQ(j["work"]["X"].get<double>(), 10.0);
    EXPECT_DOUBLE_EQ(j["work"]["Z"].get<double>(), -1.0);
    EXPECT_EQ(j["outputs"][8], 0); // OUT09, lubrication (params 733-735): off
}

// The controller reports its axis count in #1995, read-only: the gantry's drives (0 1 2 1 4) make
// five axes; a bundled machine that sets no drive has three.
TEST_F(CliOwnerBackupTest, TheAxisCountIsReadInVariable1995) {
    write("count.nc", "#100 = #1995\nM30\n");
    json j = runOk({"run", "count.nc", "--print", "100"});
    EXPECT_EQ(j["vars"]["100"], 5);
    ProcessResult bundled = sim({"run", "count.nc", "--config", std::string(M350_MACHINES_DIR) + "/m350-linear16",
                                 "--print", "100"});
    EXPECT_EQ(bundled.exitStatus, kExitOk) << bundled.err;
    EXPECT_EQ(output(bundled)["vars"]["100"], 3);
    write("write.nc", "#1995 = 4\nM30\n");
    ProcessResult refused = sim({"check", "write.nc", "--config", "machine"});
    EXPECT_EQ(refused.exitStatus, kExitError);
    EXPECT_NE(refused.err.find("write.nc:1:1: cannot write #1995 (axis count): it is read-only"), std::string::npos)
        << refused.err;
}

// K2 oils the guides: M10 switches OUT09 on, M11 off, each switch lasting param 94's 2 s.
TEST_F(CliOwnerBackupTest, KeyTwoLubricatesAndEndsWithoutAnAlarm) {
    fs::path trace = dir_ / "k2.jsonl";
    json j = runOk({"hook", "key-2", "--trace", trace.string()});
    EXPECT_EQ(j["outputs"][8], 0);
    std::vector<std::pair<int, double>> lubrication; // OUT09 levels and when
    for (const std::string& line : lines(m350::testing::readFile(trace))) {
        json e = json::parse(line);
        if (e.value("type", "") == "io" && e.value("port", "") == "OUT09") {
            lubrication.emplace_back(e["level"].get<int>(), e["t"].get<double>());
        }
    }
    ASSERT_EQ(lubrication.size(), 2u) << m350::testing::readFile(trace);
    EXPECT_EQ(lubrication[0].first, 1);
    EXPECT_EQ(lubrication[1].first, 0);
    EXPECT_NEAR(lubrication[1].second - lubrication[0].second, 2.0 + 3.0, 0.01); // M10's 2 s, G04 P3000
    // M11's 2 s; then M30's handler: M5 M9 M11 change nothing and wait for nothing
    EXPECT_NEAR(j["sim_time_s"].get<double>() - lubrication[1].second, 2.0, 0.01);
}

// K3 sets the work Z on the floating block, clearing #1922 between its probes as owners do.
TEST_F(CliOwnerBackupTest, KeyThreeProbesTheFloatingBlockClearingTheProbeStatus) {
    json j = runOk({"hook", "key-3", "--print", "100,807,1922,1927,629"});
    EXPECT_EQ(j["vars"]["1922"], 0); // cleared after the second probe
    EXPECT_DOUBLE_EQ(j["vars"]["807"].get<double>(),
                     j["vars"]["100"].get<double>() - j["vars"]["629"].get<double>());
    EXPECT_DOUBLE_EQ(j["vars"]["100"].get<double>(), j["vars"]["1927"].get<double>());
    EXPECT_DOUBLE_EQ(j["machine"]["Z"].get<double>(), j["vars"]["100"].get<double>() + 10.0);
}

// The import keeps every axis parameter (the 4th motor driving as Y, its name and limits) and
// names each parameter in real text, 969 included (the report's warning and params.toml).
TEST_F(CliOwnerBackupTest, TheImportNamesEveryParameterInRealTextAndKeepsTheAxisMapping) {
    const std::string params = m350::testing::readFile(dir_ / "machine/params.toml");
    EXPECT_NE(params.find("\n491 = 1  # 4号物理轴的编程轴 Programming axis of physical axis 4"), std::string::npos);
    EXPECT_NE(params.find("\n443 = 3  # 4th坐标轴名称 4th-axis name"), std::string::npos);
    EXPECT_NE(params.find("\n969 = 0  # T3主轴速度 Custom G code number"), std::string::npos);
    EXPECT_FALSE(looksLikeLatin1Mojibake(params));
    const json result = output(imported_);
    bool named = false;
    for (const json& problem : result["out_of_range"]) {
        named |= problem.get<std::string>() ==
                 "parameter 969 (Custom G code number) must be a whole number from 100 to 200, not 0";
    }
    EXPECT_TRUE(named) << result["out_of_range"];
    const std::string report = m350::testing::readFile(dir_ / "machine/import-report.txt");
    EXPECT_NE(report.find("parameter 969 (Custom G code number) must be a whole number from 100 to 200, not 0"),
              std::string::npos)
        << report;
    EXPECT_FALSE(looksLikeLatin1Mojibake(report)) << report;
    EXPECT_FALSE(looksLikeLatin1Mojibake(imported_.err));
    EXPECT_NE(report.find("param 491"), std::string::npos) << report; // what the simulator does of it
}

} // namespace m350::clitest
