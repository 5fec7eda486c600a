// m350-sim and tool life management: G10 L3 data written into the machine folder's toollife.txt,
// uses counted across runs, the run JSON's "tool_life", the expired group going on, a bad line.
#include "tests/cli/CliFixture.h"

namespace m350::clitest {

namespace {

class CliToolLifeTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::copy(fs::path(M350_MACHINES_DIR) / "fanuc-0i", dir_ / "machine", fs::copy_options::recursive);
    }
    ProcessResult run(const std::string& program, const std::string& text) {
        write(program, text);
        return sim({"run", program, "--config", "machine", "--print", "4120"});
    }
    std::string lifeFile() const {
        std::ifstream in(dir_ / "machine" / "toollife.txt");
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
};

} // namespace

TEST_F(CliToolLifeTest, EnteredGroupsPersistAndEachRunCountsItsUse) {
    ProcessResult entered = run("enter.nc", "G10 L3\nP1 L2 Q1\nT11 H11 D31\nT12 H12 D32\nG11\nM30\n");
    ASSERT_EQ(entered.exitStatus, kExitOk) << entered.err;
    EXPECT_NE(lifeFile().find("group 1 life 2 count\ntool 11 h 11 d 31 used 0\ntool 12 h 12 d 32 used 0\n"),
              std::string::npos)
        << lifeFile();

    for (int pass = 1; pass <= 3; ++pass) {
        ProcessResult r = run("cut.nc", "T101 M06\nT101 M06\nM30\n");
        ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
        json j = output(r);
        // T11 serves two runs (life 2), then T12
        EXPECT_EQ(j["vars"]["4120"], pass <= 2 ? 11.0 : 12.0) << pass;
        ASSERT_TRUE(j.contains("tool_life"));
        EXPECT_EQ(j["tool_life"]["in_use"]["tool"], pass <= 2 ? 11 : 12);
        EXPECT_EQ(j["tool_life"]["groups"][0]["tools"][0]["used"], std::min(pass, 2));
        EXPECT_EQ(j["tool_life"]["groups"][0]["tools"][0]["expired"], pass >= 2);
    }
    EXPECT_NE(lifeFile().find("tool 11 h 11 d 31 used 2\ntool 12 h 12 d 32 used 1\n"), std::string::npos) << lifeFile();

    ProcessResult spent = run("spent.nc", "T101 M06\nM30\n");
    ASSERT_EQ(spent.exitStatus, kExitOk) << spent.err; // T12's second and last use
    // every tool spent: FANUC goes on with the last one and raises TLCH (no alarm)
    ProcessResult again = run("again.nc", "G0 X1\nT101 M06\nM30\n");
    ASSERT_EQ(again.exitStatus, kExitOk) << again.err;
    json j = output(again);
    EXPECT_EQ(j["vars"]["4120"], 12.0);
    EXPECT_EQ(j["tool_life"]["tool_change_signal"], true);
    ASSERT_FALSE(j["messages"].empty());
    EXPECT_NE(j["messages"][0].get<std::string>().find("tool life: every tool of group 1 has reached its life"),
              std::string::npos)
        << j["messages"];
}

TEST_F(CliToolLifeTest, ABadLifeLineIsReportedWithFileLineColumnAndTheRestRuns) {
    write("machine/toollife.txt", "; group 1\ngroup 1 life 2 count\ntool 11 h 11 d 31 used 0 extra\n"
                                  "tool 12 h 12 d 32 used 1\n");
    ProcessResult r = run("p.nc", "T101 M06\nM30\n");
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("toollife.txt:3:26: error: unknown word 'extra' (line skipped)"), std::string::npos) << r.err;
    json j = output(r);
    ASSERT_EQ(j["tool_life"]["issues"].size(), 1u);
    const json& issue = j["tool_life"]["issues"][0];
    EXPECT_EQ(issue["line"], 3);
    EXPECT_EQ(issue["column"], 26);
    EXPECT_EQ(issue["severity"], "error");
    EXPECT_EQ(issue["message"], "unknown word 'extra'");
    EXPECT_NE(issue["file"].get<std::string>().find("toollife.txt"), std::string::npos);
    // T11's line was skipped: group 1 is T12 alone, which serves its second and last use
    EXPECT_EQ(j["vars"]["4120"], 12.0);
    EXPECT_EQ(j["tool_life"]["groups"][0]["tools"][0]["used"], 2);
    EXPECT_EQ(j["tool_life"]["groups"][0]["tools"][0]["remaining"], 0);
    EXPECT_EQ(j["tool_life"]["groups"][0]["tools"][0]["in_use"], true);
    // the save kept the skipped line, as a comment
    EXPECT_NE(lifeFile().find("tool 12 h 12 d 32 used 2\n; not read: tool 11 h 11 d 31 used 0 extra\n"),
              std::string::npos)
        << lifeFile();
}

TEST_F(CliToolLifeTest, AMachineWithoutGroupsKeepsTheContractAndWritesNothing) {
    ProcessResult r = run("plain.nc", "T101 M06\nM30\n");
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    expectRunContract(j);
    EXPECT_EQ(j["vars"]["4120"], 101.0);
    EXPECT_FALSE(fs::exists(dir_ / "machine" / "toollife.txt"));
}

} // namespace m350::clitest
