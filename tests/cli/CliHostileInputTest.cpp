// Issue 26: hostile machine-folder files, endless holds and huge inputs. Each case runs m350-sim
// as a user would, on scratch FIFOs and links only (a link to /dev/zero is refused before a read).
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace m350::clitest {

namespace {

class HostileInputTest : public CliTest {
  protected:
    fs::path copyMachine(const std::string& name = "m350-linear16") {
        fs::path copy = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / name, copy, fs::copy_options::recursive);
        return copy;
    }
    // m350-sim refuses the folder: exit 2, a config_error naming `file` and saying `says`.
    void expectRefused(const std::vector<std::string>& args, const std::string& file, const std::string& says) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitError) << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
        EXPECT_EQ(output(r)["alarm"].value("code", ""), "config_error") << r.out;
    }
};

} // namespace

// tool.tbl and toollife.txt were read without the check every other folder file has: a FIFO
// blocked m350-sim forever, a link to /dev/zero was read until memory ran out.
TEST_F(HostileInputTest, AToolTableOrToolLifeFileThatIsNoRegularFileIsRefusedUnread) {
    const fs::path machine = copyMachine();
    for (const char* name : {"tool.tbl", "toollife.txt"}) {
        ASSERT_EQ(::mkfifo((machine / name).c_str(), 0600), 0);
        expectRefused({"mdi", "G0 X1", "--config", "machine"}, std::string("machine/") + name,
                      "it is a FIFO (named pipe), not a regular file");
        fs::remove(machine / name);
        fs::create_symlink("/dev/zero", machine / name);
        expectRefused({"mdi", "G0 X1", "--config", "machine"}, std::string("machine/") + name,
                      "it is a device, not a regular file");
        fs::remove(machine / name);
    }
    // a table named on the command line gets the same check
    ASSERT_EQ(::mkfifo((dir_ / "pipe.tbl").c_str(), 0600), 0);
    ProcessResult r = sim({"tools", "--config", "machine", "--tool-table", "pipe.tbl"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_NE(r.err.find("pipe.tbl: cannot read the tool table: it is a FIFO"), std::string::npos) << r.err;
}

// A tool table far larger than any real one (a link to a huge file) is refused by its size.
TEST_F(HostileInputTest, AToolTableAboveTheMachineFileSizeIsRefused) {
    const fs::path machine = copyMachine();
    {
        std::ofstream big(machine / "tool.tbl", std::ios::binary);
        big << "T1 P1 Z-50\n";
    }
    fs::resize_file(machine / "tool.tbl", 17 * 1024 * 1024); // sparse: no slow write
    expectRefused({"mdi", "G0 X1", "--config", "machine"}, "machine/tool.tbl",
                  "bytes is more than a machine file can be (16 MiB)");
}

// One 100 MB program line took 4.3 GB in `run` and 6.3 GB in `check`: a line longer than 1 MiB is
// refused at its line, unread. A line just over the limit shows it; one at the limit is read.
TEST_F(HostileInputTest, AProgramLineLongerThanTheLimitIsRefusedAtItsLine) {
    const std::string atLimit = "G0 X1 (" + std::string(1024 * 1024 - 8, 'a') + ")";
    ASSERT_EQ(atLimit.size(), 1024u * 1024u);
    write("fits.nc", "G0 X0\n" + atLimit + "\nM30\n");
    ProcessResult fits = sim({"check", "fits.nc"});
    EXPECT_EQ(fits.exitStatus, kExitOk) << fits.err;

    write("long.nc", "G0 X0\n" + atLimit + "X\nM30\n");
    for (const char* command : {"check", "run"}) {
        ProcessResult r = sim({command, "long.nc"});
        EXPECT_EQ(r.exitStatus, kExitError) << r.err;
        EXPECT_NE(r.err.find("long.nc:2:1: the line is 1048577 bytes long, more than the 1048576 a program line may have"),
                  std::string::npos)
            << r.err;
        EXPECT_LT(r.err.size(), 2000u) << "the line is not echoed";
    }
}

// `m350-sim tools` listed every skipped line of a 100,000-line table and echoed whole comments:
// the same bounds as `check` (the first and last 500 findings, 512-byte echoes).
TEST_F(HostileInputTest, TheToolsListingIsBoundedAsCheckIs) {
    std::string table = "T1 P1 Z-50 ;" + std::string(5000, 'c') + "\n";
    for (int i = 0; i < 3000; ++i) {
        table += "T1x P" + std::string(2000, 'z') + "\n";
    }
    write("big.tbl", table);
    ProcessResult r = sim({"tools", "--tool-table", "big.tbl"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err.substr(0, 2000);
    const json j = output(r);
    ASSERT_EQ(j["issues"].size(), 1001u);
    EXPECT_EQ(j["issues"][500].value("omitted", 0), 2000) << j["issues"][500];
    EXPECT_EQ(j["issues"][500].value("line", 0), 502);
    EXPECT_EQ(j["issues"][1000].value("line", 0), 3001);
    for (const json& issue : j["issues"]) {
        EXPECT_LE(issue.value("message", "").size(), 600u) << issue;
    }
    EXPECT_LE(j["tools"][0].value("comment", "").size(), 600u);
    EXPECT_LT(r.out.size(), 400'000u);
    EXPECT_LT(lines(r.err).size(), 1100u) << "stderr lists the same bounded issues";
}

// `N1 M00` / `GOTO1` held and was started without end (a hold costs no virtual time): a run without
// an operator ends at once with a clear alarm; a loop whose stops have moves between them does not.
TEST_F(HostileInputTest, ARunThatOnlyAnOperatorCouldEndStopsAtOnce) {
    write("hold.nc", "N1 M00\nGOTO1\n");
    ProcessResult r = sim({"run", "hold.nc"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    const json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit");
    EXPECT_EQ(j["alarm"].value("message_id", ""), "operator_loop");
    EXPECT_EQ(j["alarm"].value("line", 0), 1);
    EXPECT_LT(j.value("sim_time_s", 1e9), 10.0) << "at once, not after --max-sim-time";
    EXPECT_NE(r.err.find("hold.nc:1:1: alarm: the program stopped for the operator at hold.nc:1 20000 times in a row "
                         "with no move between"),
              std::string::npos)
        << r.err;

    write("inspect.nc", "#1=0\nWHILE[#1LT200]DO1\nM00\n#1=#1+1\nEND1\nM30\n"); // 200 stops: an operator's checks
    ProcessResult checks = sim({"run", "inspect.nc", "--print", "1"});
    EXPECT_EQ(checks.exitStatus, kExitOk) << checks.err;
    EXPECT_EQ(output(checks)["vars"]["1"], 200);
}

// `G1 X10 E5 F100` moved X and dropped E in silence on the M350: an address it has no use for is an
// alarm at the word (FANUC's PS0009 improper NC-address), with its message id for the panel.
TEST_F(HostileInputTest, AnAddressTheM350DoesNotHaveIsAnAlarmAtTheWord) {
    ProcessResult r = sim({"mdi", "G1 X10 E5 F100"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    const json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "invalid_word");
    EXPECT_EQ(j["alarm"].value("message_id", ""), "improper_address");
    EXPECT_EQ(j["alarm"].value("column", 0), 8);
    EXPECT_EQ(j["machine"]["X"], 0.0) << "the block is not run";
    EXPECT_NE(r.err.find("E5: the M350 has no address E"), std::string::npos) << r.err;
    ProcessResult zh = sim({"mdi", "G1 X10 E5 F100", "--lang", "zh_CN"});
    EXPECT_NE(zh.err.find("M350没有地址E"), std::string::npos) << zh.err;
    EXPECT_EQ(sim({"mdi", "G1 X10 F100"}).exitStatus, kExitOk);
}

// `check` said ok to `N1 GOTO1`: a jump back over blocks none of which can leave is a lint; a loop
// with an exit (an IF before the GOTO, an M30 or M99, a WHILE, an assignment) is not.
TEST_F(HostileInputTest, CheckFlagsALoopWithoutAnExitAndNotOneWithAnExit) {
    write("endless.nc", "G0 X0\nN1 G1 X10 F100\nG1 X0\nGOTO1\nM30\n");
    ProcessResult r = sim({"check", "endless.nc"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    const json j = output(r);
    ASSERT_EQ(j["diagnostics"].size(), 1u) << j;
    EXPECT_EQ(j["diagnostics"][0].value("kind", ""), "lint");
    EXPECT_EQ(j["diagnostics"][0].value("line", 0), 4);
    EXPECT_NE(r.err.find("endless.nc:4:1: GOTO1 jumps back to N1 (line 2) and nothing in between can leave the loop"),
              std::string::npos)
        << r.err;
    write("self.nc", "N1 GOTO1\n");
    EXPECT_EQ(sim({"check", "self.nc"}).exitStatus, kExitError);

    for (const char* withExit : {"N1 G0 X1\nIF[#1GT3]GOTO2\n#1=#1+1\nGOTO1\nN2 M30\n",
                                 "#1=0\nN1 #1=#1+1\nIF[#1LT5]GOTO1\nM30\n", "N1 G0 X1\nM99\nGOTO1\n",
                                 "N1 M98 P100\nGOTO1\nO100\n#3000=1(STOP)\nM99\n", "GOTO2\nN1 G0 X1\nN2 M30\n",
                                 "WHILE[#1LT3]DO1\n#1=#1+1\nEND1\nM30\n"}) {
        write("exit.nc", withExit);
        ProcessResult ok = sim({"check", "exit.nc"});
        EXPECT_EQ(ok.exitStatus, kExitOk) << withExit << "\n" << ok.err;
    }
}

} // namespace m350::clitest
