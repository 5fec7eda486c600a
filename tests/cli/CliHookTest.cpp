// `m350-sim hook NAME`: every hook file of a machine folder runs as the panel would run it, with
// the same JSON result as `run`; names and missing files are usage errors that list the hooks.
#include "tests/cli/CliFixture.h"

namespace m350::clitest {

namespace {

// The hook names `m350-sim hook` takes, as README.md lists them.
const std::vector<std::string> kHookNames{
    "T",        "ALL_T",    "fndzero",  "fndX",     "fndY",     "fndZ",     "fndA",     "fndB",  "gotozero",
    "abszero",  "absX",     "absY",     "absZ",     "absA",     "absB",     "probe",    "mulprobe", "pause",
    "error",    "sysstart", "key-1",    "key-2",    "key-3",    "key-4",    "key-5",    "key-6", "key-7",
    "ext_button", "extnc0-1", "extnc1-1", "extnc2-1", "extnc3-1", "extnc4-1", "extnc5-1", "M3", "M4",
    "M5",       "M8",       "M9",       "M10",      "M11",      "M19",      "mdi"};

class CliHookTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", dir_ / "machine", fs::copy_options::recursive);
    }
    ProcessResult hook(std::vector<std::string> args) {
        args.insert(args.begin(), "hook");
        args.insert(args.end(), {"--config", "machine"});
        return sim(args);
    }
};

} // namespace

TEST_F(CliHookTest, EveryHookRunsFromTheMachineFolder) {
    for (std::size_t i = 0; i < kHookNames.size(); ++i) {
        write("machine/" + kHookNames[i] + ".nc", "#100=" + std::to_string(i + 1) + "\n");
    }
    for (std::size_t i = 0; i < kHookNames.size(); ++i) {
        ProcessResult r = hook({kHookNames[i], "--print", "100"});
        ASSERT_EQ(r.exitStatus, kExitOk) << kHookNames[i] << ": " << r.err;
        json j = output(r);
        expectRunContract(j);
        EXPECT_EQ(j["vars"]["100"], static_cast<double>(i + 1)) << kHookNames[i];
    }
}

TEST_F(CliHookTest, DualYGantryFndzeroHomesFourAxesWithAEqualToY) {
    write("machine/fndzero.nc", "M98P501X2\nM98P501X0\nM98P501X1\n#883=#881\n#1518=1\nM30\n");
    ProcessResult r = hook({"fndzero", "--unhomed", "--param", "123=7.25", "--print", "1515,1516,1517,1518"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    for (const char* flag : {"1515", "1516", "1517", "1518"}) {
        EXPECT_EQ(j["vars"][flag], 1.0) << flag;
    }
    EXPECT_EQ(j["machine"]["Y"], 7.25);
    EXPECT_EQ(j["machine"]["A"], 7.25);
}

TEST_F(CliHookTest, TNcTakesTheTargetToolFromVariable1504) {
    write("machine/T.nc", "T#1504\n");
    ProcessResult r = hook({"T", "--var", "1504=4"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(output(r)["tool"], 4);
}

TEST_F(CliHookTest, AnAlarmInAHookNamesItsFileLineAndColumn) {
    write("machine/key-2.nc", "#100=1\n#101=1/0\n");
    ProcessResult r = hook({"key-2"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json alarm = output(r)["alarm"];
    EXPECT_EQ(alarm["file"], "key-2.nc");
    EXPECT_EQ(alarm["line"], 2);
    EXPECT_NE(r.err.find("key-2.nc:2:"), std::string::npos) << r.err;
}

TEST_F(CliHookTest, UnknownNamesAndMissingFilesAreUsageErrorsListingTheHooks) {
    ProcessResult unknown = hook({"fndQ"});
    EXPECT_EQ(unknown.exitStatus, kExitUsage);
    EXPECT_NE(unknown.err.find("'fndQ' is no hook file"), std::string::npos) << unknown.err;
    EXPECT_NE(unknown.err.find("fndzero, fndX"), std::string::npos) << unknown.err;
    EXPECT_TRUE(unknown.out.empty()) << unknown.out;

    write("machine/key-5.nc", "#100=1\n");
    ProcessResult missing = hook({"sysstart"});
    EXPECT_EQ(missing.exitStatus, kExitUsage);
    EXPECT_NE(missing.err.find("has no sysstart.nc"), std::string::npos) << missing.err;
    const std::string::size_type listed = missing.err.find("its hook files: ");
    ASSERT_NE(listed, std::string::npos) << missing.err;
    EXPECT_NE(missing.err.find("key-5", listed), std::string::npos) << missing.err;

    ProcessResult library = hook({"slibuser"});
    EXPECT_EQ(library.exitStatus, kExitUsage) << "a library is loaded, not run";
}

TEST_F(CliHookTest, HomeRunsFndzeroWhenTheFolderHasIt) {
    write("machine/fndzero.nc", "#100=5\nM98P501X2\nM98P501X0\nM98P501X1\n");
    write("p.nc", "#101=#100\nM30\n");
    ProcessResult r = sim({"run", "p.nc", "--config", "machine", "--unhomed", "--home", "--print", "101,1515"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"]["101"], 5.0);
    EXPECT_EQ(j["vars"]["1515"], 1.0);
}

} // namespace m350::clitest
