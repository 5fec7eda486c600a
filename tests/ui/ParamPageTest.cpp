// 参数管理 and 系统管理 as an operator uses them: levels and passwords, refused and accepted values,
// params.toml after a restart, search, backup and restore, the #50-#499 view, 密码设置.
#include "tests/ui/PanelHarness.h"
#include "ui/panel/PromptBox.h"

#include "ui/pages/ParamPage.h"
#include "ui/pages/SystemPage.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/panel/StatusLine.h"
#include "ui/session/UserAccess.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

namespace m350::test {

namespace {

using params::UserLevel;

QString readFile(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// 搜索: the number typed at 请输入搜索的参数编号:
void search(PanelHarness& panel, int number) {
    panel.softkey(2);
    panel.type(QString::number(number));
    panel.key("ENTER");
}

// Enter on the selected parameter, then the value (and the password first when one is asked).
void enterValue(PanelHarness& panel, const QString& value, const QString& password = {}) {
    panel.key("ENTER");
    if (!password.isEmpty()) {
        panel.type(password);
        panel.key("ENTER");
    }
    panel.type(value);
    panel.key("ENTER");
}

// 切换权限 (the Param page's F9, the System page's F6): the level's number, then its password.
void changeLevel(PanelHarness& panel, int level, const QString& password, int softkey = 9) {
    panel.softkey(softkey);
    panel.type(QString::number(level));
    panel.key("ENTER");
    panel.type(password);
    panel.key("ENTER");
}

double parameter(PanelHarness& panel, int number) { return panel.session().latest()->status.parameters.get(number); }

} // namespace

TEST(ParamPage, OutOfRangeIsRefusedAValidValueIsKeptInParamsTomlAcrossARestart) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    {
        PanelHarness panel(*folder);
        panel.key("PARAM");
        auto* page = panel.page<ui::ParamPage>();
        ASSERT_NE(page, nullptr);
        search(panel, 61); // 缺省加工速度, 1-99999 mm/min, user tab
        ASSERT_EQ(page->selectedNumber(), 61);
        EXPECT_EQ(page->tab(), ui::ParamPage::Tab::User);
        enterValue(panel, "123456", ui::UserAccess::defaultPassword(UserLevel::Operator));
        EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("[61]号参数输入的数据非法!")))
            << panel.window().messageText().toStdString();
        EXPECT_EQ(parameter(panel, 61), 3000.0);
        enterValue(panel, "2500");
        EXPECT_EQ(parameter(panel, 61), 2500.0);
        QString params = readFile(QDir(*folder).filePath("params.toml"));
        EXPECT_TRUE(params.contains(QStringLiteral("61 = 2500  # default feed, mm/min"))) << params.toStdString();
        EXPECT_TRUE(params.startsWith(QStringLiteral("# Parameters of the default machine"))) << "comments kept";
    }
    PanelHarness restarted(*folder);
    EXPECT_EQ(parameter(restarted, 61), 2500.0);
    restarted.key("PARAM");
    search(restarted, 61);
    auto* page = restarted.page<ui::ParamPage>();
    EXPECT_EQ(page->state()["param_value"].toString(), "2500.000");
}

TEST(ParamPage, SearchFindsANumberOnItsTabAndGroupAndSaysWhenThereIsNone) {
    PanelHarness panel;
    panel.key("PARAM");
    auto* page = panel.page<ui::ParamPage>();
    EXPECT_EQ(page->tab(), ui::ParamPage::Tab::Factory);
    search(panel, 545); // X home switch: the input port table
    EXPECT_EQ(page->selectedNumber(), 545);
    EXPECT_EQ(page->state()["param_group"].toInt(), 16);
    EXPECT_EQ(page->state()["param_tab"].toString(), "factory");
    search(panel, 129); // floating setter thickness: 对刀参数 on the user tab
    EXPECT_EQ(page->selectedNumber(), 129);
    EXPECT_EQ(page->tab(), ui::ParamPage::Tab::User);
    EXPECT_TRUE(page->infoText().contains(QStringLiteral("对刀参数"))) << page->infoText().toStdString();
    EXPECT_TRUE(page->infoText().contains(QStringLiteral("设定范围: 0 ~ 99")));
    search(panel, 1027);
    EXPECT_EQ(page->selectedNumber(), 129) << "a CAM-teach number is not on these pages";
    EXPECT_TRUE(panel.window().messageText().contains("1027"));
}

TEST(ParamPage, AGuestIsAskedForAPasswordAndAWrongOneChangesNothing) {
    PanelHarness panel;
    panel.key("PARAM");
    EXPECT_EQ(panel.window().statusLine()->levelText(), QStringLiteral("访客"));
    search(panel, 129);
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().state()["prompt"].toString().contains(QStringLiteral("请输入[操作员]及以上密码")));
    EXPECT_TRUE(panel.window().prompt()->secret()) << "a password is typed as dots";
    panel.type("wrong1");
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("解锁密码输入错误!")));
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Guest);
    EXPECT_TRUE(panel.window().state()["prompt"].toString().isEmpty()) << "no value is asked";
    enterValue(panel, "12.5", ui::UserAccess::defaultPassword(UserLevel::Operator));
    EXPECT_EQ(parameter(panel, 129), 12.5);
    EXPECT_EQ(panel.window().statusLine()->levelText(), QStringLiteral("操作员"));
}

TEST(ParamPage, AFactoryParameterNeedsAdminAndTheOperatorPasswordDoesNotOpenIt) {
    PanelHarness panel;
    panel.key("PARAM");
    changeLevel(panel, 1, ui::UserAccess::defaultPassword(UserLevel::Operator));
    ASSERT_EQ(panel.session().userLevel(), UserLevel::Operator);
    search(panel, 1); // X pulses per mm, 机床参数
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().state()["prompt"].toString().contains(QStringLiteral("[管理员]")));
    panel.type(ui::UserAccess::defaultPassword(UserLevel::Operator));
    panel.key("ENTER");
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Operator);
    enterValue(panel, "800", ui::UserAccess::defaultPassword(UserLevel::Super));
    EXPECT_EQ(panel.session().userLevel(), UserLevel::Super) << "a higher level's password opens the higher level";
    EXPECT_EQ(parameter(panel, 1), 800.0);
}

TEST(ParamPage, BackupThenRestorePutsTheValuesBackAndABrokenBackupChangesNothing) {
    PanelHarness panel;
    panel.key("PARAM");
    changeLevel(panel, 2, ui::UserAccess::defaultPassword(UserLevel::Admin));
    panel.softkey(3); // 参数备份
    QString backup = QDir(panel.folder()).filePath("params-backup.toml");
    ASSERT_TRUE(QFile::exists(backup)) << panel.window().messageText().toStdString();
    search(panel, 61);
    enterValue(panel, "2500");
    ASSERT_EQ(parameter(panel, 61), 2500.0);
    panel.softkey(4); // 参数恢复
    panel.key("ENTER"); // yes
    EXPECT_EQ(parameter(panel, 61), 3000.0) << panel.window().messageText().toStdString();
    EXPECT_TRUE(readFile(QDir(panel.folder()).filePath("params.toml")).contains("61 = 3000  #"));
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("1 项改变"))) << panel.window().messageText().toStdString();

    QString text = readFile(backup).replace(QStringLiteral("\n61 = 3000"), QStringLiteral("\n61 = fast"));
    QFile broken(backup);
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
    broken.write(text.toUtf8());
    broken.close();
    enterValue(panel, "2500");
    panel.softkey(4);
    panel.key("ENTER");
    EXPECT_EQ(parameter(panel, 61), 2500.0);
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("params-backup.toml:68:")))
        << panel.window().messageText().toStdString();
}

TEST(ParamPage, TheVariableViewShowsAndSetsCommonVariables) {
    PanelHarness panel;
    panel.key("PARAM");
    panel.softkey(5); // #50-#499
    auto* page = panel.page<ui::ParamPage>();
    ASSERT_TRUE(page->variablesShown());
    panel.key("DOWN");
    EXPECT_EQ(page->selectedNumber(), 51);
    enterValue(panel, "12.5", ui::UserAccess::defaultPassword(UserLevel::Operator));
    EXPECT_EQ(page->valueText(1), "12.5000");
    panel.key("ESC");
    EXPECT_FALSE(page->variablesShown());
}

TEST(SystemPage, ShowsTheVersionAndChangesThePasswordOfTheCurrentLevel) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    {
        PanelHarness panel(*folder);
        panel.key("SYSTEM");
        auto* page = panel.page<ui::SystemPage>();
        ASSERT_NE(page, nullptr);
        EXPECT_EQ(page->fieldText("version"), QStringLiteral(M350_VERSION));
        EXPECT_FALSE(panel.window().softkeys()->enabled(1)); // 软件注册
        EXPECT_TRUE(panel.window().softkeys()->enabled(2));  // 密码设置
        panel.softkey(2); // a guest is asked to sign in first
        EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("权限不足")));
        panel.key("ESC");
        changeLevel(panel, 1, ui::UserAccess::defaultPassword(UserLevel::Operator), 6);
        panel.softkey(2);
        panel.type("short");
        panel.key("ENTER");
        EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("小于6个")));
        panel.softkey(2);
        panel.type("lathe-42");
        panel.key("ENTER");
        panel.type("lathe-42");
        panel.key("ENTER");
        EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("密码修改成功!")));
        QString stored = readFile(QDir(*folder).filePath("passwords.toml"));
        EXPECT_TRUE(stored.contains("operator = \""));
        EXPECT_FALSE(stored.contains("lathe-42")) << "kept hashed";
    }
    PanelHarness restarted(*folder);
    EXPECT_FALSE(restarted.session().login(UserLevel::Operator, ui::UserAccess::defaultPassword(UserLevel::Operator)));
    EXPECT_TRUE(restarted.session().login(UserLevel::Operator, "lathe-42"));
}

} // namespace m350::test
