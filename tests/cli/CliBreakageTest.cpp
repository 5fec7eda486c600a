// Tool breakage through m350-sim on the bundled fanuc-ts27r machine: --break makes a tool shorter
// (before the run or at a virtual time), G65 P9858 finds it on the setter, the spindle load
// monitor finds it in the cut, and the run JSON carries the load history ("spindle_load").
#include "tests/cli/CliFixture.h"

namespace m350::clitest {

namespace {

const std::string kMachine = std::string(M350_MACHINES_DIR) + "/fanuc-ts27r";

const char* kCut = "G90 G49\nS6000 M03\nG00 X-150 Y0\nG00 Z-355\nG01 Z-362 F300\nG01 X150 F600\nG00 Z0\nM05\nM30\n";

class CliBreakageTest : public CliTest {
  protected:
    json simTs27r(std::vector<std::string> args, int exitStatus) {
        args.insert(args.end(), {"--config", kMachine, "--tool", "1"});
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err << r.out;
        json j = output(r);
        EXPECT_TRUE(j.contains("spindle_load")) << j;
        json contract = j;
        contract.erase("spindle_load");
        expectRunContract(contract);
        return j;
    }
};

} // namespace

TEST_F(CliBreakageTest, TheSetterCheckSaysHowShortABrokenToolIs) {
    json ok = simTs27r({"mdi", "G91 G28 Z0", "G65 P9858 T1 H0.5", "--print", "135,136"}, kExitOk);
    EXPECT_NEAR(ok["vars"]["135"].get<double>(), 120.0, 1e-9);
    json broken = simTs27r({"mdi", "G91 G28 Z0", "G65 P9858 T1 H0.5", "--break", "T1=0.62"}, kExitAlarm);
    EXPECT_EQ(broken["alarm"]["code"], "macro_alarm");
    EXPECT_EQ(broken["alarm"]["message"], "macro alarm 3094: tool 1 broken: 0.62 mm short, tolerance 0.5");
    EXPECT_EQ(broken["alarm"]["file"], "breakage.nc");
}

TEST_F(CliBreakageTest, TheLoadMonitorStopsTheCutAndTheHistoryIsInTheJson) {
    write("cut.nc", kCut);
    json intact = simTs27r({"run", "cut.nc", "--print", "1032"}, kExitOk);
    // the last sample: the spindle idling at 6000 rpm, 3.3 % -> L 756 -> 14300 x 756 / 32767 = 329.9
    EXPECT_EQ(intact["vars"]["1032"], 329.0);
    const json& load = intact["spindle_load"];
    EXPECT_EQ(load["lambda"], 143.0);
    EXPECT_EQ(load["register_variable"], 1032);
    EXPECT_EQ(load["limits"]["1"]["lower"], 10.0);
    EXPECT_LE(load["samples"].size(), 600u);
    EXPECT_EQ(load["taken"].get<std::size_t>(), load["samples"].size()); // 36 s of samples: all kept
    bool cut = false;
    for (const json& s : load["samples"]) {
        cut = cut || (s[1] == 1 && s[2] == 33.29);
    }
    EXPECT_TRUE(cut) << load["samples"];

    json broken = simTs27r({"run", "cut.nc", "--break", "T1=0.62@12.05"}, kExitAlarm);
    EXPECT_EQ(broken["alarm"]["code"], "spindle_load");
    EXPECT_EQ(broken["alarm"]["line"], 6);
    EXPECT_LT(broken["machine"]["X"].get<double>(), 149.0);
    const json& last = broken["spindle_load"]["samples"].back();
    EXPECT_EQ(last[2], 3.29);
}

TEST_F(CliBreakageTest, LoadLimitsOnTheCommandLineReplaceTheFilesOnes) {
    write("cut.nc", kCut);
    // an upper limit below the cut's 33.29 %: the overload stops it
    json j = simTs27r({"run", "cut.nc", "--load-limits", "T1=5:30"}, kExitAlarm);
    EXPECT_EQ(j["alarm"]["code"], "spindle_load");
    EXPECT_NE(j["alarm"]["message"].get<std::string>().find("(above)"), std::string::npos) << j["alarm"];
    EXPECT_EQ(j["spindle_load"]["limits"]["1"]["upper"], 30.0);
}

TEST_F(CliBreakageTest, BadBreakAndLimitOptionsAreUsageErrors) {
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"--break", "T1"}, {"--break", "T0=1"}, {"--break", "T1=-2"}, {"--break", "T1=1@x"},
          {"--load-limits", "T1=60:10"}, {"--load-limits", "T1=5"}}) {
        std::vector<std::string> args{"mdi", "G4 P1", "--config", kMachine};
        args.insert(args.end(), bad.begin(), bad.end());
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitUsage) << bad[1] << ": " << r.err;
        EXPECT_NE(r.err.find(bad[0]), std::string::npos) << r.err;
    }
}

// Lambda is FANUC parameter 4127 (params.toml holds 143): --param changes the conversion. At
// lambda 200 the idling spindle's 3.3 % is L = round(3.3 / 200 x 32767) = 541 and the register
// floor(100 x 200 x 541 / 32767) = 330.
TEST_F(CliBreakageTest, LambdaIsParameter4127) {
    write("cut.nc", kCut);
    json j = simTs27r({"run", "cut.nc", "--print", "1032", "--param", "4127=200"}, kExitOk);
    EXPECT_EQ(j["spindle_load"]["lambda"], 200.0);
    EXPECT_EQ(j["vars"]["1032"], 330.0);

    ProcessResult outOfRange = sim({"mdi", "G4 P1", "--config", kMachine, "--param", "4127=0"});
    EXPECT_EQ(outOfRange.exitStatus, kExitUsage) << outOfRange.err;
    EXPECT_NE(outOfRange.err.find("parameter 4127 must be from 1 to 1000"), std::string::npos) << outOfRange.err;

    ProcessResult unread = sim({"mdi", "G4 P1", "--config", kMachine, "--param", "1320=5"});
    EXPECT_EQ(unread.exitStatus, kExitOk) << unread.err;
    EXPECT_NE(unread.err.find("FANUC parameter 1320 is not simulated"), std::string::npos) << unread.err;

    ProcessResult m350 = sim({"mdi", "G4 P1", "--param", "4127=200"}); // the default machine speaks m350
    EXPECT_EQ(m350.exitStatus, 64) << m350.err;
    EXPECT_NE(m350.err.find("parameters run from 0 to 999 on an M350 machine"), std::string::npos) << m350.err;
}

} // namespace m350::clitest
