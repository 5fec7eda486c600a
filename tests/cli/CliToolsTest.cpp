// The tool table from the command line: `m350-sim tools` lists the machine folder's tool.tbl (or
// --tool-table FILE) as a run starts with it, a run reads it (#2001, #1430) and --tools-out writes
// what the run left; bad lines are reported with file:line:col.
#include "tests/cli/CliFixture.h"

namespace m350::clitest {

namespace {

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

constexpr const char* kFanucTable = ";shop tools\n"
                                    "T1 P1 Z+25.000000 D+10.000000 ;face mill {rpm=6000 teeth=5 type=face}\n"
                                    "T7\tP3\tZ12.5 ;spot drill\n";

class CliToolsTest : public CliTest {
  protected:
    void copyMachine(const char* name) {
        fs::copy(fs::path(M350_MACHINES_DIR) / name, dir_ / "machine", fs::copy_options::recursive);
    }
};

} // namespace

TEST_F(CliToolsTest, ToolsListsTheFoldersTableByteForByteAndAsJson) {
    copyMachine("fanuc-0i");
    write("machine/tool.tbl", kFanucTable);
    ProcessResult text = sim({"tools", "--config", "machine", "--tbl"});
    ASSERT_EQ(text.exitStatus, kExitOk) << text.err;
    EXPECT_EQ(text.out, kFanucTable);
    ProcessResult r = sim({"tools", "--config", "machine"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["status"], "ok");
    EXPECT_EQ(keysOf(j), (std::set<std::string>{"status", "file", "tools", "issues"}));
    ASSERT_EQ(j["tools"].size(), 2u);
    const json& t1 = j["tools"][0];
    EXPECT_EQ(t1["tool"], 1);
    EXPECT_EQ(t1["z"], 25.0);
    EXPECT_EQ(t1["diameter"], 10.0);
    EXPECT_EQ(t1["max_rpm"], 6000.0);
    EXPECT_EQ(t1["teeth"], 5);
    EXPECT_EQ(t1["type"], "face");
    EXPECT_EQ(t1["comment"], "face mill");
    EXPECT_EQ(j["tools"][1]["pocket"], 3);
}

TEST_F(CliToolsTest, ABadLineIsReportedWithFileLineAndColumnAndTheRestIsListed) {
    copyMachine("fanuc-0i");
    write("machine/tool.tbl", "T1 P1 Z1\nT2 P2 Z2 S9000\nT3 P1 Z3\n");
    ProcessResult r = sim({"tools", "--config", "machine"});
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(j["status"], "error");
    ASSERT_EQ(j["issues"].size(), 2u);
    EXPECT_EQ(j["issues"][0]["line"], 2);
    EXPECT_EQ(j["issues"][0]["column"], 10);
    EXPECT_EQ(j["issues"][1]["line"], 3);
    EXPECT_NE(j["issues"][1]["message"].get<std::string>().find("pocket 1 already holds a tool (line 1)"),
              std::string::npos);
    EXPECT_EQ(j["tools"].size(), 1u);
    EXPECT_NE(r.err.find("tool.tbl:2:10: error: 'S' is no tool table word"), std::string::npos) << r.err;
}

TEST_F(CliToolsTest, ARunReadsTheTableAndToolsOutWritesWhatTheRunLeft) {
    copyMachine("fanuc-0i");
    write("machine/tool.tbl", kFanucTable);
    write("touch.nc", "G10 L2 P1 Z-100.\nG90 G54 G00 Z0\n#100 = #2007\nG10 L10 P7 Z-2.\nG43 H7\nM30\n");
    ProcessResult r = sim({"run", "touch.nc", "--config", "machine", "--tools-out", "after.tbl", "--print", "100,2007,5043"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    expectRunContract(j);
    EXPECT_EQ(j["vars"]["100"], 12.5);
    EXPECT_EQ(j["vars"]["2007"], 2.0) << "-100 - (-100) - (-2)";
    EXPECT_EQ(j["vars"]["5043"], -2.0);
    EXPECT_EQ(readText(dir_ / "after.tbl"), ";shop tools\n"
                                             "T1 P1 Z+25.000000 D+10.000000 ;face mill {rpm=6000 teeth=5 type=face}\n"
                                             "T7 P3 Z2 ;spot drill\n");
    EXPECT_EQ(readText(dir_ / "machine/tool.tbl"), kFanucTable) << "a simulation leaves the machine folder alone";
}

TEST_F(CliToolsTest, OnTheM350TheTablesZIsTheToolsParameter) {
    copyMachine("m350-linear16");
    write("lathe.tbl", "T1 P1 Z-60 ;from LinuxCNC\n");
    ProcessResult r = sim({"mdi", "#1431 = -44.5", "--config", "machine", "--tool-table", "lathe.tbl", "--print",
                           "1430,1431", "--tools-out", "after.tbl"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"]["1430"], -60.0) << "the table's T1 Z is parameter 930";
    const std::string after = readText(dir_ / "after.tbl");
    EXPECT_EQ(after.rfind("T1 P1 Z-60 ;from LinuxCNC\n", 0), 0u) << after;
    EXPECT_NE(after.find("\nT2 P2 Z-44.5\n"), std::string::npos) << "#1431 is T2's row" << after;
    ProcessResult listed = sim({"tools", "--config", "machine", "--tbl"});
    ASSERT_EQ(listed.exitStatus, kExitOk) << listed.err;
    EXPECT_NE(listed.out.find("T17 P17 Z-40.25\n"), std::string::npos) << "virtual tools from params 973+" << listed.out;
}

TEST_F(CliToolsTest, AToolTableThatCannotBeReadIsAFileError) {
    ProcessResult r = sim({"tools", "--tool-table", "missing.tbl"});
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(j["status"], "error");
    EXPECT_NE(r.err.find("missing.tbl"), std::string::npos) << r.err;
}

} // namespace m350::clitest
