// Issue 26: m350-sim --level runs MDI lines and programs as the panel's user level would (a
// parameter above it stops the run), and reset-passwords is the explicit repair of a
// passwords.toml the panel cannot trust.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace m350::clitest {

namespace {

class UserRightsTest : public CliTest {
  protected:
    fs::path copyMachine() {
        fs::path copy = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", copy, fs::copy_options::recursive);
        return copy;
    }
};

} // namespace

TEST_F(UserRightsTest, AGuestsMdiLineWritesNoParameterTheParamPageRefusesIt) {
    copyMachine();
    ProcessResult guest = sim({"mdi", "#1301=3", "--config", "machine", "--level", "guest", "--print", "1301"});
    EXPECT_EQ(guest.exitStatus, kExitAlarm) << guest.err;
    json j = output(guest);
    EXPECT_EQ(j["alarm"].value("code", ""), "rights_limited") << j;
    EXPECT_EQ(j["alarm"].value("message_id", ""), "parameter_rights") << j;
    EXPECT_EQ(j["vars"]["1301"], 16.0) << "the magazine keeps its 16 pockets";
    EXPECT_NE(guest.err.find("MDI:1:1: "), std::string::npos) << guest.err;

    ProcessResult zh = sim({"mdi", "#629=77", "--config", "machine", "--level", "operator", "--lang", "zh_CN"});
    EXPECT_EQ(zh.exitStatus, kExitOk) << "129 is a user-tab parameter: an operator sets it\n" << zh.err;
    ProcessResult factory = sim({"mdi", "#1000=1", "--config", "machine", "--level", "operator", "--lang", "zh_CN"});
    EXPECT_EQ(factory.exitStatus, kExitAlarm);
    EXPECT_NE(factory.err.find("权限不足"), std::string::npos) << factory.err;
    EXPECT_NE(factory.err.find("参数500需要管理员(当前操作员)"), std::string::npos) << factory.err;

    // no --level: nobody stands at a panel, m350-sim writes as before
    ProcessResult anyone = sim({"mdi", "#1301=3", "--config", "machine", "--print", "1301"});
    EXPECT_EQ(anyone.exitStatus, kExitOk) << anyone.err;
    EXPECT_EQ(output(anyone)["vars"]["1301"], 3.0);
}

TEST_F(UserRightsTest, TheMachinesOwnMacroWritesItsParametersForAGuest) {
    copyMachine();
    // O502 (slib-probe.nc) on the fixed setter writes T1's Z, param 930 (#1430), back from 0
    ProcessResult probe = sim({"mdi", "M98 P502", "--config", "machine", "--level", "guest", "--param", "930=0", "--var",
                               "1502=1", "--print", "1430"});
    EXPECT_EQ(probe.exitStatus, kExitOk) << probe.err;
    EXPECT_NEAR(output(probe)["vars"]["1430"].get<double>(), -53.677, 1e-3);
    ProcessResult typed = sim({"mdi", "#1430=0", "--config", "machine", "--level", "guest"});
    EXPECT_EQ(typed.exitStatus, kExitAlarm) << "the same parameter typed by the guest";
}

TEST_F(UserRightsTest, ResetPasswordsReplacesAFifoAndRefusesAFolder) {
    fs::path machine = copyMachine();
    ASSERT_EQ(::mkfifo((machine / "passwords.toml").c_str(), 0600), 0);
    ProcessResult reset = sim({"reset-passwords", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_EQ(reset.exitStatus, kExitOk) << reset.err;
    json j = output(reset);
    EXPECT_EQ(j.value("status", ""), "ok");
    EXPECT_EQ(j.value("message_id", ""), "passwords_reset");
    EXPECT_NE(reset.err.find("已重新写入"), std::string::npos) << reset.err;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(machine / "passwords.toml")));
    std::ifstream log(machine / "system-log.tsv");
    std::string text{std::istreambuf_iterator<char>(log), {}};
    EXPECT_NE(text.find("\tpasswords_reset\t"), std::string::npos) << text;

    fs::remove(machine / "passwords.toml");
    fs::create_directory(machine / "passwords.toml");
    ProcessResult folder = sim({"reset-passwords", "--config", "machine"});
    EXPECT_EQ(folder.exitStatus, kExitError);
    EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
    ProcessResult folderChinese = sim({"reset-passwords", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_EQ(folderChinese.exitStatus, kExitError);
    EXPECT_NE(folderChinese.err.find("m350-sim: reset-passwords: machine/passwords.toml是文件夹：请手动删除，未写入任何内容"),
              std::string::npos)
        << folderChinese.err;

    ProcessResult usage = sim({"reset-passwords"});
    EXPECT_EQ(usage.exitStatus, 64) << "the folder is never guessed";
}

// The System Log's own failure (system-log.tsv is a folder) is said in the language asked, framed
// by the warning that the reset went unlogged; the reset itself is done.
TEST_F(UserRightsTest, ASystemLogThatCannotBeReadIsSaidInEitherLanguage) {
    fs::path machine = copyMachine();
    fs::create_directory(machine / "system-log.tsv");
    ProcessResult chinese = sim({"reset-passwords", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_NE(chinese.err.find("m350-sim: 警告：系统日志未能记录此次重置：machine/system-log.tsv：无法读取系统日志："),
              std::string::npos)
        << chinese.err;
    EXPECT_EQ(chinese.err.find("cannot"), std::string::npos) << chinese.err;
    ProcessResult english = sim({"reset-passwords", "--config", "machine", "--lang", "en"});
    EXPECT_EQ(english.exitStatus, kExitOk) << english.err;
    EXPECT_NE(english.err.find("m350-sim: warning: the System Log did not take the reset: machine/system-log.tsv: cannot "
                               "read the system log: "),
              std::string::npos)
        << english.err;
    EXPECT_EQ(output(english).value("message_id", ""), "passwords_reset");
}

} // namespace m350::clitest
