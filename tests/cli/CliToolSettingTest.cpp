// 对刀 through m350-sim on the default machine, with the M350 manual's numbers (setter X Y Z
// 555.269 / 66.381 / -53.677, 3 passes, back 50): its world puts the setter's top at -120, so T3
// (58.695 mm) trips at machine Z -61.305 and T2 (71.88 mm) at -48.12. O502, O505, O506, O507 are
// slib-probe.nc's; probe.nc and mulprobe.nc call them as the Probe page does.
#include "tests/cli/CliFixture.h"

#include <algorithm>

namespace m350::clitest {

namespace {

const std::string kMachine = std::string(M350_MACHINES_DIR) + "/m350-linear16";

class CliToolSettingTest : public CliTest {
  protected:
    // Runs m350-sim with the manual's setter Z start, returning the JSON (with the exit status checked).
    // That start is T1's trip height: a longer tool (T2 trips at -48.12) needs one above it, or the
    // rapid down to it drives the tool into the setter (a crash): `probeStart` -30 is the folder's.
    json simManual(std::vector<std::string> args, int exitStatus, const std::string& probeStart = "-53.677") {
        args.insert(args.end(), {"--config", kMachine, "--param", "137=" + probeStart});
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err << r.out;
        json j = output(r);
        expectRunContract(j);
        return j;
    }
    // The fixed setting of T3 (#1502 = 2) ending in the given alarm.
    json alarmOfSetting(std::vector<std::string> extra, const std::string& code) {
        std::vector<std::string> args{"mdi", "M98P502", "--var", "1502=2", "--print", "1432"};
        args.insert(args.end(), extra.begin(), extra.end());
        if (std::find(extra.begin(), extra.end(), "--tool") == extra.end()) {
            args.insert(args.end(), {"--tool", "3"});
        }
        json j = simManual(args, kExitAlarm);
        EXPECT_EQ(j["alarm"]["code"], code) << j;
        EXPECT_EQ(j["alarm"]["file"], "slib-probe.nc") << j;
        EXPECT_EQ(j["vars"]["1432"], -61.305) << "T3's offset must stay as params.toml has it";
        return j;
    }
};

} // namespace

TEST_F(CliToolSettingTest, FixedSettingFromMdiStoresTheTripHeight) {
    json j = simManual({"mdi", "M98P502", "--var", "1502=2", "--tool", "3", "--param", "932=0", "--print", "1432,1508"},
                       kExitOk);
    EXPECT_NEAR(j["vars"]["1432"].get<double>(), -61.305, 1e-9);
    EXPECT_EQ(j["vars"]["1508"], 0.0);
    EXPECT_NEAR(j["machine"]["X"].get<double>(), 555.269, 1e-9);
    EXPECT_NEAR(j["machine"]["Y"].get<double>(), 66.381, 1e-9);
    EXPECT_NEAR(j["machine"]["Z"].get<double>(), -61.305 + 1 + 50, 1e-9); // run-up 1, back 50
    EXPECT_EQ(j["messages"].back(), "对刀完成!");
}

TEST_F(CliToolSettingTest, TheProbeHookDoesTheSameAndTheFirstSettingMovesG54Z) {
    // T3 not set yet: G54 Z -12.5 becomes -12.5 + 0 - (-61.305) = 48.805 (A = B - C - D)
    json j = simManual({"hook", "probe", "--var", "1502=1", "--tool", "3", "--param", "932=0", "--print",
                        "1432,807,1508"},
                       kExitOk);
    EXPECT_NEAR(j["vars"]["1432"].get<double>(), -61.305, 1e-9);
    EXPECT_NEAR(j["vars"]["807"].get<double>(), 48.805, 1e-9);
    EXPECT_EQ(j["vars"]["1508"], 1.0);
}

TEST_F(CliToolSettingTest, FloatingSettingSetsTheActiveWorkZ) {
    // the block (10 mm) lies on the work: T1 trips at -122.5 + 66.323 = -56.177; G54 Z = -56.177 -
    // 10 - (-53.677) = -12.5
    json j = simManual({"mdi", "G53 X300 Y200 Z-40", "M98P502", "G00 Z0", "--var", "1502=0", "--print", "807"},
                       kExitOk);
    EXPECT_NEAR(j["vars"]["807"].get<double>(), -12.5, 1e-9);
    EXPECT_NEAR(j["machine"]["Z"].get<double>(), -12.5 + -53.677, 1e-9);
}

TEST_F(CliToolSettingTest, MultiToolSettingChangesToAndSetsEachListedTool) {
    json j = simManual({"hook", "mulprobe", "--var", "1970=2", "--var", "1971=3", "--param", "931=0", "--param",
                        "932=0", "--print", "1431,1432,1993"},
                       kExitOk, "-30");
    EXPECT_NEAR(j["vars"]["1431"].get<double>(), -48.12, 1e-9);
    EXPECT_NEAR(j["vars"]["1432"].get<double>(), -61.305, 1e-9);
    EXPECT_EQ(j["vars"]["1993"], 0.0);
    EXPECT_EQ(j["tool"], 3);
    EXPECT_EQ(j["messages"].back(), "多刀对刀完成! 2把刀");
}

TEST_F(CliToolSettingTest, AMultiToolSettingStoppedByAnAlarmKeepsTheToolsSetBeforeIt) {
    json j = simManual({"hook", "mulprobe", "--var", "1970=2", "--var", "1971=40", "--param", "931=0", "--print",
                        "1431,1993"},
                       kExitAlarm, "-30");
    EXPECT_EQ(j["alarm"]["code"], "macro_alarm");
    EXPECT_NEAR(j["vars"]["1431"].get<double>(), -48.12, 1e-9);
    EXPECT_EQ(j["vars"]["1993"], 0.0);
    EXPECT_EQ(j["tool"], 2);
}

TEST_F(CliToolSettingTest, Param805SetsTheToolAtTheEndOfTheChange) {
    json j = simManual({"mdi", "T2", "--param", "805=1", "--param", "931=0", "--print", "1431"}, kExitOk, "-30");
    EXPECT_NEAR(j["vars"]["1431"].get<double>(), -48.12, 1e-9);
    EXPECT_EQ(j["tool"], 2);
}

TEST_F(CliToolSettingTest, TeachStoresTheMachinePosition) {
    json j = simManual({"mdi", "G53 X512.5 Y70.25 Z-44.5", "M98P506", "M98P507", "--print", "635,636,637"}, kExitOk);
    EXPECT_EQ(j["vars"]["635"], 512.5);
    EXPECT_EQ(j["vars"]["636"], 70.25);
    EXPECT_EQ(j["vars"]["637"], -44.5);
}

TEST_F(CliToolSettingTest, ASlowSetterSignalStillWithinToleranceShiftsTheAverage) {
    // heard 10 ms late: (250 + 125 + 62.5) / 60 x 0.01 / 3 = 0.024306 mm below the trip height
    json j = simManual({"mdi", "M98P502", "--var", "1502=2", "--tool", "3", "--fault", "IN12=delayed:0.01", "--print",
                        "1432"},
                       kExitOk);
    EXPECT_NEAR(j["vars"]["1432"].get<double>(), -61.305 - 437.5 / 60 * 0.01 / 3, 1e-9);
}

TEST_F(CliToolSettingTest, EachAlarmOfTheSetting) {
    alarmOfSetting({"--input", "IN12=0"}, "skip_not_triggered"); // the setter never trips
    json disagree = alarmOfSetting({"--fault", "IN12=delayed:0.05"}, "macro_alarm");
    EXPECT_NE(disagree["alarm"]["message"].get<std::string>().find("3006"), std::string::npos);
    EXPECT_EQ(disagree["messages"].back(), "对刀误差 0.156 mm, 允许 0.050 mm");
    const std::vector<std::pair<std::vector<std::string>, std::string>> macroAlarms{
        {{"--tool", "0"}, "macro alarm 3001: 当前刀位空刀不能对刀!"},
        {{"--unhomed"}, "macro alarm 3002: X,Y,Z轴机械未全部归零! home X, Y and Z before setting a tool"},
        {{"--param", "130=0"}, "macro alarm 3004: 固定对刀仪无效! the fixed setter is switched off: param 130"},
        {{"--param", "576=0"},
         "macro alarm 3005: 固定对刀信号未设置! the fixed setter input, params 575-577, is not set"},
    };
    for (const auto& [extra, message] : macroAlarms) {
        json j = alarmOfSetting(extra, "macro_alarm");
        EXPECT_EQ(j["alarm"]["message"], message);
    }
}

TEST_F(CliToolSettingTest, FloatingSetterSwitchedOffIsAnAlarm) {
    json j = simManual({"mdi", "M98P502", "--var", "1502=0", "--param", "128=0"}, kExitAlarm);
    EXPECT_EQ(j["alarm"]["message"], "macro alarm 3004: 浮动对刀仪无效! the floating setter is switched off: param 128");
}

TEST_F(CliToolSettingTest, FaultOptionsAreChecked) {
    for (const char* bad : {"IN12=late:0.05", "IN12=delayed", "IN30=delayed:0.1", "IN12=stuck:2", "IN12=bouncing:-1",
                            "X12=delayed:0.1"}) {
        ProcessResult r = sim({"mdi", "G00 X1", "--fault", bad});
        EXPECT_EQ(r.exitStatus, kExitUsage) << bad << ": " << r.out;
        EXPECT_NE(r.err.find("--fault"), std::string::npos) << r.err;
    }
    ProcessResult stuck = sim({"mdi", "#100=#1531", "--fault", "IN12=stuck:1", "--print", "100"});
    ASSERT_EQ(stuck.exitStatus, kExitOk) << stuck.err;
    EXPECT_EQ(output(stuck)["vars"]["100"], 1.0);
}

} // namespace m350::clitest
