// Issue 26 "nobody in": what a guest types at the panel changes no protected parameter, every
// parameter change reaches the System Log with the level, a changed password never falls back to
// the published default, and a passwords.toml that cannot be trusted locks every level above Guest.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/MdiPage.h"
#include "ui/pages/SystemPage.h"
#include "ui/panel/PromptBox.h"
#include "ui/session/UserAccess.h"

#include "core/config/PasswordsFile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace m350::test {

namespace {

using params::UserLevel;
namespace fs = std::filesystem;

double parameter(PanelHarness& panel, int number) { return panel.session().latest()->status.parameters.get(number); }

QString systemLog(PanelHarness& panel) { return fileText(QDir(panel.folder()).filePath("system-log.tsv")); }

// The MDI page's first line, typed and run (执行).
void runMdi(PanelHarness& panel, const QString& line) {
    panel.key("MDI");
    panel.type(line);
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(1.0);
}

QString password(UserLevel level) { return ui::UserAccess::defaultPassword(level); }

// Whether any of the three protected levels opens with its published default.
bool aDefaultOpens(PanelHarness& panel) {
    for (UserLevel level : {UserLevel::Operator, UserLevel::Admin, UserLevel::Super}) {
        if (panel.session().login(level, password(level))) {
            return true;
        }
    }
    return false;
}

} // namespace

// `#1301=3` (param 801, the magazine's capacity) and `#629=77` (param 129, the floating setter's
// thickness) were taken from a guest's MDI line although the Param page refuses a guest both.
TEST(UserRights, AGuestsMdiLineIsRefusedAndThePasswordIsAskedAsTheParamPageAsksIt) {
    PanelHarness panel;
    ASSERT_EQ(parameter(panel, 801), 16.0);
    runMdi(panel, "#1301=3");
    EXPECT_EQ(parameter(panel, 801), 16.0);
    auto s = panel.session().latest();
    ASSERT_TRUE(s->status.alarm);
    EXPECT_EQ(s->status.alarm->code, AlarmCode::RightsLimited);
    EXPECT_TRUE(panel.window().alarmText().contains(QStringLiteral("参数801需要操作员(当前访客)")))
        << panel.window().alarmText().toStdString();
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("权限不足"))) << panel.window().messageText().toStdString();
    ASSERT_TRUE(panel.window().prompt()->active()) << "the password of the level it needs";
    EXPECT_TRUE(panel.window().prompt()->question().contains(QStringLiteral("操作员")))
        << panel.window().prompt()->question().toStdString();
    panel.type(password(UserLevel::Operator));
    panel.key("ENTER");
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Operator);
    panel.key("RESET");
    panel.softkey(1); // the same line again, now as an operator
    panel.advance(1.0);
    EXPECT_EQ(parameter(panel, 801), 3.0);
    const QString log = systemLog(panel);
    EXPECT_TRUE(log.contains(QStringLiteral("param_operator\t[801] 16 -> 3 (mdi.nc:1)"))) << log.toStdString();
    EXPECT_FALSE(log.contains(QStringLiteral("param_guest"))) << "the guest changed nothing";
}

TEST(UserRights, AGuestsProgramLineCannotSetTheSetterThicknessEither) {
    PanelHarness panel;
    const double before = parameter(panel, 129);
    runMdi(panel, "#629=77");
    EXPECT_EQ(parameter(panel, 129), before);
    ASSERT_TRUE(panel.session().latest()->status.alarm);
    EXPECT_EQ(panel.session().latest()->status.alarm->code, AlarmCode::RightsLimited);
}

// The machine's own macros write what they write: O502 (slib-probe.nc) run from a guest's MDI line
// sets the tool's Z parameter, and the System Log names the level and the library's line.
TEST(UserRights, TheMachinesMacrosStillWriteAndEveryChangeIsLoggedWithTheLevel) {
    PanelHarness panel;
    panel.session().setParameter(930, 0.0); // the setup, through the session: T1 not yet set
    panel.session().setVariable(1502, 1.0); // O502's fixed setter mode
    runMdi(panel, "M98 P502");
    panel.advance(60.0);
    EXPECT_FALSE(panel.session().latest()->status.alarm) << panel.window().alarmText().toStdString();
    EXPECT_NEAR(parameter(panel, 930), -53.677, 1e-3) << panel.page<ui::MdiPage>()->resultText().toStdString();
    const QString log = systemLog(panel);
    EXPECT_TRUE(log.contains(QStringLiteral("param_guest\t[930] 0 -> -53.677 (slib-probe.nc:99)"))) << log.toStdString();
}

// The tool table's touch off writes the tool's Z (930 for T1): a guest is asked the operator's password.
TEST(UserRights, TouchOffAsAGuestAsksTheOperatorsPassword) {
    PanelHarness panel;
    const double before = parameter(panel, 930);
    panel.key("PROBE");
    panel.softkey(2); // 刀具表
    panel.softkey(4); // touch off
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("权限不足"))) << panel.window().messageText().toStdString();
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.type("wrong-1");
    panel.key("ENTER");
    EXPECT_EQ(parameter(panel, 930), before);
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Guest);
    panel.softkey(4);
    panel.type(password(UserLevel::Operator));
    panel.key("ENTER");
    ASSERT_TRUE(panel.window().prompt()->active()) << "then the touch off's own question";
    while (!panel.window().prompt()->textValue().isEmpty()) {
        panel.key("BACKSPACE");
    }
    panel.type("2");
    panel.key("ENTER");
    EXPECT_NE(parameter(panel, 930), before);
    EXPECT_TRUE(systemLog(panel).contains(QStringLiteral("param_operator\t[930] "))) << systemLog(panel).toStdString();
}

// `operator = "<salt>:<hash>" # changed` and upper-case hex skipped the line, and opr350 opened the
// level again.
TEST(UserRights, AChangedPasswordNeverFallsBackToTheDefault) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    const QString file = QDir(*folder).filePath("passwords.toml");
    {
        PanelHarness panel(*folder);
        ASSERT_TRUE(panel.session().login(UserLevel::Operator, password(UserLevel::Operator)));
        ASSERT_FALSE(panel.session().changePassword("lathe-42"));
    }
    const QString written = fileText(file);
    QString commented;
    for (const QString& line : written.split('\n')) {
        commented += line + (line.startsWith(QStringLiteral("operator")) ? QStringLiteral(" # changed\n") : QStringLiteral("\n"));
    }
    for (const QString& text : {commented, written.toUpper().replace(QStringLiteral("OPERATOR"), QStringLiteral("operator"))}) {
        putFile(file, text.toUtf8());
        PanelHarness panel(*folder);
        EXPECT_TRUE(panel.session().passwordsProblem().isEmpty()) << panel.session().passwordsProblem().toStdString();
        EXPECT_FALSE(panel.session().login(UserLevel::Operator, password(UserLevel::Operator))) << text.toStdString();
        EXPECT_TRUE(panel.session().login(UserLevel::Operator, "lathe-42")) << text.toStdString();
        EXPECT_TRUE(panel.session().login(UserLevel::Admin, password(UserLevel::Admin))) << "admin was never changed";
    }
}

// A passwords.toml that cannot be trusted brought the published defaults back. Now only Guest
// opens, the System page and the System Log say why, and the explicit reset repairs it.
TEST(UserRights, ACorruptPasswordsFileLocksEveryLevelAboveGuest) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    const fs::path file = fs::path(folder->toStdString()) / "passwords.toml";
    const fs::path scratch = fs::path(dir.path().toStdString());
    ASSERT_EQ(::mkfifo((scratch / "fifo").c_str(), 0600), 0);
    {
        std::ofstream big(scratch / "big", std::ios::binary);
        big.seekp(64 * 1024 * 1024);
        big << "x"; // sparse: 64 MiB that are never read
    }
    auto put = [&](const std::string& text) {
        fs::remove_all(file);
        std::ofstream(file, std::ios::binary) << text;
    };
    auto link = [&](const fs::path& to) {
        fs::remove_all(file);
        fs::create_symlink(to, file);
    };
    const std::vector<std::pair<std::string, std::function<void()>>> cases{
        {"bad TOML", [&] { put("operator = \"abc\n[[[\n"); }},
        {"binary", [&] {
             static constexpr char kElf[] = "\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe";
             put(std::string(kElf, sizeof kElf - 1));
         }},
        {"a folder", [&] { fs::remove_all(file); fs::create_directory(file); }},
        {"a link to /dev/null", [&] { link("/dev/null"); }},
        {"a FIFO", [&] { fs::remove_all(file); ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0); }},
        {"a link to a FIFO", [&] { link(scratch / "fifo"); }},
        {"a huge file", [&] { link(scratch / "big"); }},
        {"not hex", [&] { put("operator = \"zz:zz\"\n"); }},
        {"an unknown level", [&] { put("operater = \"00:00\"\n"); }},
    };
    for (const auto& [what, make] : cases) {
        make();
        PanelHarness panel(*folder);
        EXPECT_FALSE(panel.session().passwordsProblem().isEmpty()) << what;
        EXPECT_FALSE(aDefaultOpens(panel)) << what;
        EXPECT_EQ(panel.session().userLevel(), UserLevel::Guest) << what;
        panel.key("SYSTEM");
        auto* page = panel.page<ui::SystemPage>();
        ASSERT_NE(page, nullptr);
        EXPECT_TRUE(page->fieldText("passwords").contains(QStringLiteral("m350-sim reset-passwords"))) << what;
        EXPECT_TRUE(page->fieldText("passwords").contains(QStringLiteral("访客"))) << what;
        EXPECT_TRUE(systemLog(panel).contains(QStringLiteral("passwords_locked\t"))) << what;
    }
    // the explicit reset writes the file anew: the defaults open again, at the next login
    PanelHarness panel(*folder);
    EXPECT_FALSE(aDefaultOpens(panel));
    ASSERT_FALSE(config::resetPasswords(config::MachineFolder(file.parent_path())));
    EXPECT_TRUE(panel.session().login(UserLevel::Super, password(UserLevel::Super)));
    EXPECT_TRUE(panel.session().passwordsProblem().isEmpty());
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(file)));
}

// The highest level, still signed in when the file went bad, repairs it by setting its password:
// every level keeps the password it had (the operator's changed one, not opr350).
TEST(UserRights, TheHighestLevelRepairsABadFileWithoutBringingADefaultBack) {
    PanelHarness panel;
    const fs::path file = fs::path(panel.folder().toStdString()) / "passwords.toml";
    ASSERT_TRUE(panel.session().login(UserLevel::Operator, password(UserLevel::Operator)));
    ASSERT_FALSE(panel.session().changePassword("lathe-42"));
    ASSERT_TRUE(panel.session().login(UserLevel::Super, password(UserLevel::Super)));
    std::ofstream(file, std::ios::binary | std::ios::trunc) << "operator = \"zz:zz\"\n";
    EXPECT_FALSE(panel.session().login(UserLevel::Admin, password(UserLevel::Admin)));
    EXPECT_FALSE(panel.session().passwordsProblem().isEmpty());
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Super) << "the level signed in stays";
    EXPECT_FALSE(panel.session().changePassword("super-new-1"));
    EXPECT_TRUE(panel.session().passwordsProblem().isEmpty());
    PanelHarness restarted(panel.folder());
    EXPECT_TRUE(restarted.session().passwordsProblem().isEmpty());
    EXPECT_FALSE(restarted.session().login(UserLevel::Operator, password(UserLevel::Operator)));
    EXPECT_TRUE(restarted.session().login(UserLevel::Operator, "lathe-42"));
    EXPECT_TRUE(restarted.session().login(UserLevel::Super, "super-new-1"));
}

} // namespace m350::test
