// Issue 13: machine-folder values that hung m350-sim, allocated until memory ran out, read files
// outside the folder or were silently ignored. Each is refused (or warned about) naming
// file:line:col.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>

namespace m350::clitest {

namespace {

class MachineFolderTest : public CliTest {
  protected:
    // A copy of a bundled machine in the scratch folder, as "machine".
    fs::path copyMachine(const std::string& name = "m350-linear16") {
        fs::path copy = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / name, copy, fs::copy_options::recursive);
        return copy;
    }
    static std::string read(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    // Replaces the first `from` in `file` by `to`.
    static void edit(const fs::path& file, const std::string& from, const std::string& to) {
        std::string text = read(file);
        ASSERT_NE(text.find(from), std::string::npos) << from;
        text.replace(text.find(from), from.size(), to);
        std::ofstream(file, std::ios::binary) << text;
    }
    // The run refuses the folder as a config error placed at `where` (file:line:col).
    void expectConfigError(const std::vector<std::string>& args, const std::string& where, const std::string& says) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitError) << r.err;
        EXPECT_NE(r.err.find(where + ": "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
        json alarm = output(r)["alarm"];
        EXPECT_EQ(alarm.value("code", ""), "config_error") << alarm;
        EXPECT_GT(alarm.value("line", 0), 0) << alarm;
        EXPECT_GT(alarm.value("column", 0), 0) << alarm;
    }
};

} // namespace

// A capacity of 1e9 built a table of a billion pockets (1.7 GB in 20 s, then on); inf was ignored.
TEST_F(MachineFolderTest, AHugeMagazineCapacityIsRefusedWhereverItIsGiven) {
    fs::path machine = copyMachine();
    edit(machine / "params.toml", "801 = 16", "801 = 1000000000");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/params.toml:71:7", "magazine capacity");

    ProcessResult option = sim({"mdi", "G0 X1", "--param", "801=1e9"});
    EXPECT_EQ(option.exitStatus, kExitUsage) << option.err;
    EXPECT_NE(option.err.find("parameter 801 (magazine capacity) must be a whole number from 0 to 999"),
              std::string::npos)
        << option.err;

    fs::remove_all(machine);
    machine = copyMachine("fanuc-0i");
    const std::string text = read(fs::path(M350_MACHINES_DIR) / "fanuc-0i" / "machine.toml");
    const std::string capacityLine = std::to_string(std::count(text.begin(), text.end(), '\n') + 2);
    for (const char* capacity : {"1000000000", "inf", "-5", "2.5"}) {
        std::ofstream(machine / "machine.toml", std::ios::binary) << text << "[magazine]\ncapacity = " << capacity << "\n";
        expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:" + capacityLine + ":12",
                          "'capacity' must be a whole number from 0 to 999");
    }
}

// A library at /dev/zero or a FIFO read (or waited) forever; an absolute path outside the folder
// was read and its lines echoed in the syntax errors.
TEST_F(MachineFolderTest, ALibraryMustBeAProgramFileInsideTheFolder) {
    fs::path machine = copyMachine();
    edit(machine / "machine.toml", "g = \"slib-g.nc\"", "g = \"/dev/zero\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");
    edit(machine / "machine.toml", "g = \"/dev/zero\"", "g = \"/etc/passwd\"");
    ProcessResult passwd = sim({"mdi", "G0 X1", "--config", "machine"});
    EXPECT_EQ(passwd.exitStatus, kExitError);
    EXPECT_EQ(passwd.err.find("root:"), std::string::npos) << passwd.err;
    EXPECT_EQ(passwd.out.find("root:"), std::string::npos) << passwd.out;

    ASSERT_EQ(::mkfifo((machine / "pipe.nc").c_str(), 0600), 0);
    edit(machine / "machine.toml", "g = \"/etc/passwd\"", "g = \"pipe.nc\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "FIFO");
    fs::create_symlink("/dev/zero", machine / "zero.nc");
    edit(machine / "machine.toml", "g = \"pipe.nc\"", "g = \"zero.nc\"");
    // a link out of the folder is refused before anything follows it (issue 26)
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");

    ProcessResult program = sim({"run", "machine/pipe.nc"});
    EXPECT_EQ(program.exitStatus, kExitError) << program.err;
    EXPECT_NE(program.err.find("not a program file"), std::string::npos) << program.err;
}

// Issue 26: `g = "../../../../etc/passwd"` left the folder by a relative path, and a symlink in
// the folder led anywhere; either was read and its lines echoed in the syntax errors.
TEST_F(MachineFolderTest, ALibraryStaysInsideTheFolderAfterDotsAndSymlinks) {
    fs::create_directories(dir_ / "elsewhere");
    std::ofstream(dir_ / "elsewhere" / "secret.nc", std::ios::binary) << "SECRET-LINE ~~~ not g-code\n";
    fs::path machine = copyMachine();
    edit(machine / "machine.toml", "g = \"slib-g.nc\"", "g = \"../../../../../../../../etc/passwd\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");
    edit(machine / "machine.toml", "g = \"../../../../../../../../etc/passwd\"", "g = \"../elsewhere/secret.nc\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");
    fs::create_symlink(dir_ / "elsewhere" / "secret.nc", machine / "evil.nc");
    edit(machine / "machine.toml", "g = \"../elsewhere/secret.nc\"", "g = \"evil.nc\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");
    ProcessResult echoed = sim({"mdi", "G0 X1", "--config", "machine"});
    EXPECT_EQ(echoed.err.find("SECRET-LINE"), std::string::npos) << echoed.err;
    EXPECT_EQ(echoed.out.find("SECRET-LINE"), std::string::npos) << echoed.out;

    // a folder the user names in M350_LIBRARIES is one more place a library may lie
    fs::remove(machine / "evil.nc");
    fs::copy_file(machine / "slib-g.nc", dir_ / "elsewhere" / "shared-g.nc");
    fs::create_symlink(dir_ / "elsewhere" / "shared-g.nc", machine / "evil.nc");
    ::setenv("M350_LIBRARIES", (dir_ / "elsewhere").c_str(), 1);
    ProcessResult named = sim({"mdi", "G0 X1", "--config", "machine"});
    ::unsetenv("M350_LIBRARIES");
    EXPECT_EQ(named.exitStatus, kExitOk) << named.err;

    // a machine folder beside it (a copy of the bundled machines) lends its .nc libraries only
    fs::create_directories(dir_ / "other");
    std::ofstream(dir_ / "other" / "machine.toml") << "name = \"other\"\n";
    std::ofstream(dir_ / "other" / "passwords.toml") << "operator = \"SECRET-LINE\"\n";
    fs::copy_file(machine / "slib-g.nc", dir_ / "other" / "lib.nc");
    edit(machine / "machine.toml", "g = \"evil.nc\"", "g = \"../other/passwords.toml\"");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/machine.toml:8:5", "outside the machine folder");
    edit(machine / "machine.toml", "g = \"../other/passwords.toml\"", "g = \"../other/lib.nc\"");
    EXPECT_EQ(sim({"mdi", "G0 X1", "--config", "machine"}).exitStatus, kExitOk);
}

// Typos in the machine folder were silently ignored; `G54 = "abc"` too.
TEST_F(MachineFolderTest, UnknownKeysAreWarnedAboutAndAWrongOffsetIsAnError) {
    fs::path machine = copyMachine();
    edit(machine / "machine.toml", "fork_depth = 30.0", "fork_dept = 30.0");
    std::ofstream(machine / "params.toml", std::ios::app) << "[parms]\n61 = 3000\n";
    ProcessResult r = sim({"mdi", "G0 X1", "--config", "machine"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("machine/machine.toml:21:1: warning: unknown key 'magazine.fork_dept'"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("machine/params.toml:153:2: warning: unknown key 'parms'"), std::string::npos) << r.err;

    std::ofstream(machine / "offsets.toml", std::ios::binary) << "# offsets\nG54 = \"abc\"\n";
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/offsets.toml:2:7", "G54 must be [X, Y, Z, A, B]");
    std::ofstream(machine / "offsets.toml", std::ios::binary) << "G54 = [1.0, \"abc\"]\n";
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/offsets.toml:1:13", "must be a number");
}

// Issue 26: an offset with fewer than X Y Z values and an empty machine.toml loaded without a word.
TEST_F(MachineFolderTest, ShortOffsetsAndAnEmptyMachineFileAreWarnedAbout) {
    fs::path machine = copyMachine();
    std::ofstream(machine / "offsets.toml", std::ios::binary) << "G54 = [1.0]\n";
    ProcessResult shortOffset = sim({"mdi", "G54 G0 X0", "--config", "machine"});
    EXPECT_EQ(shortOffset.exitStatus, kExitOk) << shortOffset.err;
    EXPECT_NE(shortOffset.err.find("machine/offsets.toml:1:7: warning: G54 has 1 value for [X, Y, Z, A, B]: the axes "
                                   "it leaves out are 0"),
              std::string::npos)
        << shortOffset.err;
    EXPECT_DOUBLE_EQ(output(shortOffset)["machine"]["X"].get<double>(), 1.0);

    fs::path empty = dir_ / "empty";
    fs::create_directories(empty);
    std::ofstream(empty / "machine.toml", std::ios::binary) << "";
    ProcessResult r = sim({"mdi", "G0 X1", "--config", "empty"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("empty/machine.toml: warning: empty: the machine is an M350"), std::string::npos) << r.err;
}

// A TOML error or a nan named the line only inside the message, with line 0 in the JSON.
TEST_F(MachineFolderTest, TomlErrorsAndBadValuesArePlacedByLineAndColumn) {
    fs::path machine = copyMachine();
    edit(machine / "params.toml", "811 = 6000", "811 = nan");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/params.toml:79:7", "must be a finite number");
    edit(machine / "params.toml", "811 = nan", "811 = = 6000");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/params.toml:79:7", "");
}

// FANUC parameters above 999 live in params.toml on FANUC machines only; lambda is one of them,
// not a machine.toml key.
TEST_F(MachineFolderTest, FanucParametersAreParamsOfFanucMachinesOnly) {
    fs::path m350 = copyMachine();
    edit(m350 / "params.toml", "801 = 16", "801 = 16\n4127 = 143");
    expectConfigError({"mdi", "G0 X1", "--config", "machine"}, "machine/params.toml:72:1", "from 0 to 999");
    fs::remove_all(m350);

    fs::path fanuc = copyMachine("fanuc-ts27r");
    edit(fanuc / "machine.toml", "[spindle_load]\n", "[spindle_load]\nlambda = 150\n");
    expectConfigError({"mdi", "G4 P1", "--config", "machine"}, "machine/machine.toml:48:10",
                      "[spindle_load] lambda is FANUC parameter 4127: set it in params.toml");
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 25: a parameter params.toml does not set has its factory value (the catalogue's default)
// for the macros too; one it sets has that value.
TEST_F(MachineFolderTest, AParameterTheFolderDoesNotSetReadsAsItsFactoryValue) {
    fs::path machine = copyMachine();
    ASSERT_EQ(read(machine / "params.toml").find("\n172 ="), std::string::npos) << "172 is left to its default";
    ProcessResult r = sim({"mdi", "#100 = #672", "#101 = #676", "--config", "machine", "--print", "100,101"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_NEAR(j["vars"]["100"].get<double>(), 0.004, 1e-12) << "手轮X1距离 (param 172)";
    EXPECT_NEAR(j["vars"]["101"].get<double>(), 20.0, 1e-12) << "手轮X1速度 (param 176)";

    std::ofstream(machine / "params.toml", std::ios::app) << "172 = 0.01\n";
    ProcessResult set = sim({"mdi", "#100 = #672", "--config", "machine", "--print", "100"});
    ASSERT_EQ(set.exitStatus, kExitOk) << set.err;
    EXPECT_NEAR(output(set)["vars"]["100"].get<double>(), 0.01, 1e-12) << "the folder's value wins";
}

} // namespace m350::clitest
