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

} // namespace m350::clitest
