// Issue 13: inputs that hung or crashed m350-sim. nan and infinity are never positions, feeds or
// times (each of these hung it at 100 % CPU, the virtual clock never passing the runaway guard,
// or turned the guard off); homing and symlink loops below.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace m350::clitest {

TEST_F(CliTest, ANanOrInfiniteValueOnTheCommandLineIsAUsageError) {
    for (std::vector<std::string> args : {std::vector<std::string>{"mdi", "G1 X#1 F100", "--var", "1=nan"},
                                          {"mdi", "T2", "--param", "811=nan"},
                                          {"mdi", "G1 X1 F100", "--param", "61=inf"},
                                          {"mdi", "G1 X1 F100", "--max-sim-time", "nan"},
                                          {"mdi", "G1 X1 F100", "--sensor-timeout", "inf"}}) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitUsage) << args[2] << " " << args[3] << ": " << r.err;
        EXPECT_NE(r.err.find("finite"), std::string::npos) << r.err;
    }
}

TEST_F(CliTest, ArithmeticThatOverflowsAlarmsOnItsLine) {
    ProcessResult r = sim({"mdi", "#1=1000000000*1000000000", "#2=#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1",
                           "G1 X#2 F100"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json alarm = output(r)["alarm"];
    EXPECT_EQ(alarm.value("code", ""), "invalid_argument");
    EXPECT_EQ(alarm.value("line", 0), 2);
    EXPECT_NE(alarm.value("message", "").find("overflow"), std::string::npos) << alarm;
}

TEST_F(CliTest, ANanInParamsTomlIsRefusedNamingTheLine) {
    std::filesystem::path machine = std::filesystem::path(M350_MACHINES_DIR) / "m350-linear16";
    std::filesystem::path copy = write("machine/keep", "").parent_path();
    std::filesystem::copy(machine, copy,
                          std::filesystem::copy_options::overwrite_existing | std::filesystem::copy_options::recursive);
    std::ifstream in(copy / "params.toml");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("811 = "), 6, "811 = nan #");
    write("machine/params.toml", text);
    ProcessResult r = sim({"mdi", "G0 X1", "--config", copy.string()});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_NE(r.err.find("params.toml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'811' must be a finite number, not nan"), std::string::npos) << r.err;
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: `--home --param 106=1000000000` ran for hours of wall time; the runaway guard now
// holds inside homing too.
TEST_F(CliTest, HomingStopsAtTheSimulatedTimeLimit) {
    ProcessResult r = sim({"mdi", "G0 X1", "--home", "--param", "106=1000000000", "--max-sim-time", "60"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json alarm = output(r)["alarm"];
    EXPECT_EQ(alarm.value("code", ""), "simulated_time_limit") << alarm;
    EXPECT_NE(alarm.value("message", "").find("parameter 106"), std::string::npos) << alarm;
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: a symlink loop (as the program, the machine folder or a library) aborted m350-sim with
// an uncaught filesystem exception; it is an error with a message and exit status 2.
TEST_F(CliTest, ASymlinkLoopIsAnErrorNotAnAbort) {
    std::filesystem::create_symlink("loop-b", dir_ / "loop-a");
    std::filesystem::create_symlink("loop-a", dir_ / "loop-b");
    ProcessResult program = sim({"run", "loop-a"});
    EXPECT_EQ(program.exitStatus, kExitError) << program.err;
    EXPECT_NE(program.err.find("symbolic links"), std::string::npos) << program.err;
    ProcessResult folder = sim({"mdi", "G0 X1", "--config", "loop-a"});
    EXPECT_EQ(folder.exitStatus, kExitError) << folder.err;
    EXPECT_NE(folder.err.find("symbolic links"), std::string::npos) << folder.err;

    std::filesystem::path machine = write("machine/keep", "").parent_path();
    std::filesystem::copy(std::filesystem::path(M350_MACHINES_DIR) / "m350-linear16", machine,
                          std::filesystem::copy_options::overwrite_existing | std::filesystem::copy_options::recursive);
    std::filesystem::remove(machine / "slib-g.nc");
    std::filesystem::create_symlink("slib-g.nc", machine / "slib-g.nc");
    ProcessResult library = sim({"mdi", "G0 X1", "--config", machine.string()});
    EXPECT_EQ(library.exitStatus, kExitError) << library.err;
    EXPECT_NE(library.err.find("slib-g.nc"), std::string::npos) << library.err;
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: --tool -1 / 99999 ran with garbage and --var 1520=1 was silently dropped.
TEST_F(CliTest, AToolOrVariableTheMachineCannotHaveIsAUsageError) {
    ProcessResult negative = sim({"mdi", "G0 X1", "--tool", "-1"});
    EXPECT_EQ(negative.exitStatus, kExitUsage) << negative.err;
    ProcessResult huge = sim({"mdi", "G0 X1", "--tool", "99999"});
    EXPECT_EQ(huge.exitStatus, kExitUsage) << huge.err;
    EXPECT_NE(huge.err.find("magazine capacity 16"), std::string::npos) << huge.err;
    ProcessResult virtualTool = sim({"mdi", "G0 X1", "--tool", "30"});
    EXPECT_EQ(virtualTool.exitStatus, kExitOk) << virtualTool.err << " (T17-T36 are the default machine's virtual tools)";
    ProcessResult input = sim({"mdi", "G0 X1", "--var", "1520=1"});
    EXPECT_EQ(input.exitStatus, kExitUsage) << input.err;
    EXPECT_NE(input.err.find("#1520 (input IN01) is read-only"), std::string::npos) << input.err;
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: a move of years (F0.001 over 100 m) ran to its end in one step; the report said the
// limit's 10 s but showed 6e9 s and the move's end point.
TEST_F(CliTest, ALongMoveStopsWhereTheTimeLimitFindsIt) {
    ProcessResult r = sim({"mdi", "G1 X100000 F0.001", "--param", "166=1000000000", "--max-sim-time", "10"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit") << j["alarm"];
    EXPECT_DOUBLE_EQ(j.value("sim_time_s", 0.0), 10.0);
    EXPECT_LT(j["machine"].value("X", 1e9), 1.0) << "X moves 0.001 mm/min from 0: " << j["machine"];

    ProcessResult dwell = sim({"mdi", "G4 P99999999", "--max-sim-time", "10"});
    EXPECT_EQ(dwell.exitStatus, kExitAlarm) << dwell.err;
    EXPECT_DOUBLE_EQ(output(dwell).value("sim_time_s", 0.0), 10.0);
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: `--config ""` ran the default machine as if nothing was said.
TEST_F(CliTest, AnEmptyFileOrFolderNameIsAUsageError) {
    for (std::vector<std::string> args : {std::vector<std::string>{"mdi", "G0 X1", "--config", ""},
                                          {"check", "p.nc", "--config", ""},
                                          {"mdi", "G0 X1", "--trace", ""},
                                          {"mdi", "G0 X1", "--dprnt", ""},
                                          {"mdi", "G0 X1", "--tools-out", ""},
                                          {"tools", "--tool-table", ""}}) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitUsage) << args[0] << " " << args[args.size() - 2] << ": " << r.err;
        EXPECT_NE(r.err.find("an empty name is no file or folder"), std::string::npos) << r.err;
    }
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: an unreadable program was a syntax_error at 0:0, and a native homing alarm printed
// ":0:0: alarm:".
TEST_F(CliTest, UnreadableFilesAndHomingAlarmsSayWhere) {
    write("bad.nc", "G0 X1\n(\xFF\xFF)\nM30\n");
    ProcessResult bad = sim({"run", "bad.nc"});
    EXPECT_EQ(bad.exitStatus, kExitError);
    json alarm = output(bad)["alarm"];
    EXPECT_EQ(alarm.value("code", ""), "file_error") << alarm;
    EXPECT_EQ(alarm.value("line", 0), 2) << alarm;
    EXPECT_NE(bad.err.find("bad.nc:2:2: file is neither valid UTF-8 nor GBK"), std::string::npos) << bad.err;

    const std::string fanuc = std::string(M350_MACHINES_DIR) + "/fanuc-0i";
    ProcessResult homing = sim({"mdi", "G0 X1", "--home", "--config", fanuc});
    EXPECT_EQ(homing.exitStatus, kExitAlarm) << homing.err;
    EXPECT_EQ(homing.err.find(":0:0"), std::string::npos) << homing.err;
    EXPECT_NE(homing.err.find(fanuc + "/params.toml: alarm: Z cannot home: no home switch is set (params 551-553"),
              std::string::npos)
        << homing.err;
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 13: `T2.5` alarms inside slib-g.nc's O20000; the message named only slib-g.nc:51, not the
// user's line that called it.
TEST_F(CliTest, AnAlarmInALibraryAlsoNamesTheUsersLine) {
    write("prog.nc", "G0 X1\nT2.5\nM30\n");
    ProcessResult r = sim({"run", "prog.nc"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_EQ(output(r)["alarm"].value("file", ""), "slib-g.nc");
    EXPECT_NE(r.err.find("prog.nc:2: note: the alarm is in the library this line called"), std::string::npos) << r.err;

    write("own.nc", "G0 X1\n#1=1/0\nM30\n");
    ProcessResult own = sim({"run", "own.nc"});
    EXPECT_EQ(own.err.find("note:"), std::string::npos) << own.err;
}

} // namespace m350::clitest
