// The Panel menu's 导入控制器备份 as an owner uses it: the menu action, the two folders, the
// report in the panel's prompt and the offer to switch, answered with the panel's keys; then the
// panel restarted on the new folder shows the backup's MDI lines and parameters.
#include "tests/support/ControllerBackupWriter.h"
#include "tests/ui/PanelHarness.h"
#include "ui/panel/BackupImportFlow.h"
#include "ui/panel/PromptBox.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>

namespace m350::test {

namespace {

using m350::testing::ControllerBackupWriter;

// Answers the two folder questions as an owner picking them in the file dialogs would.
void chooseFolders(PanelHarness& panel, const QString& backup, const QString& into, QStringList* asked) {
    panel.window().backupImport().setFolderChooser(
        [=](const QString& caption, const QString&, bool existing) {
            asked->append(caption);
            return existing ? backup : into;
        });
}

void triggerMenuEntry(PanelHarness& panel) {
    auto* action = panel.window().findChild<QAction*>(QStringLiteral("importBackupAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->text(), QStringLiteral("导入控制器备份..."));
    action->trigger();
    ASSERT_TRUE(panel.window().backupImport().waitForImport(30000));
    ui::settle(panel.session());
}

} // namespace

TEST(PanelBackupImport, TheMenuEntryImportsReportsAndSwitchesToTheNewMachine) {
    QTemporaryDir dir;
    ControllerBackupWriter backup = ControllerBackupWriter::smallRouter();
    backup.writeTo(QDir(dir.path()).filePath("SYSDISK").toStdString());
    const QString into = QDir(dir.path()).filePath("my-router");
    QString switchedTo;
    QStringList asked;
    {
        PanelHarness panel;
        chooseFolders(panel, QDir(dir.path()).filePath("SYSDISK"), into, &asked);
        panel.window().backupImport().setSwitcher([&switchedTo](const QString& folder) { switchedTo = folder; });
        triggerMenuEntry(panel);
        EXPECT_EQ(asked.size(), 2);
        ASSERT_TRUE(panel.window().prompt()->active());
        const QString report = panel.window().prompt()->question();
        EXPECT_TRUE(report.contains(into)) << report.toStdString();
        // the core's words in the panel's language too (message ids): the magazine and what cannot be modelled
        EXPECT_TRUE(report.contains(QStringLiteral("刀库类型4（圆盘刀库），容量6：未建模，无刀库装置"))) << report.toStdString();
        EXPECT_TRUE(report.contains(QStringLiteral("模拟器无法模拟:\n- 刀库类型4（圆盘刀库）无法从备份建模"))) << report.toStdString();
        EXPECT_FALSE(report.contains(QStringLiteral("servo disc"))) << report.toStdString();
        EXPECT_FALSE(report.contains(QStringLiteral("not modelled"))) << report.toStdString();
        // and the machine folder's import-report.txt in the language of the import that made it
        QFile written(QDir(into).filePath(QStringLiteral("import-report.txt")));
        ASSERT_TRUE(written.open(QIODevice::ReadOnly));
        EXPECT_EQ(QString::fromUtf8(written.readLine()).trimmed(), QStringLiteral("由控制器备份生成的机器文件夹（本报告为中文）"));
        EXPECT_TRUE(report.endsWith(QStringLiteral("是否将面板切换到此机床?"))) << report.toStdString();
        panel.key("ENTER");
        EXPECT_FALSE(panel.window().prompt()->active());
        EXPECT_EQ(switchedTo, into);
    }
    PanelHarness restarted(switchedTo);
    restarted.page("mdi");
    const QJsonArray lines = restarted.window().state()[QStringLiteral("mdi_lines")].toArray();
    ASSERT_EQ(lines.size(), 6);
    EXPECT_EQ(lines[0].toString(), QStringLiteral("G90 G0 X20 Y10"));
    EXPECT_EQ(lines[3].toString(), QStringLiteral("(MDI 测试)"));
    EXPECT_EQ(restarted.session().latest()->status.parameters.get(129), backup.setting[129]);
}

TEST(PanelBackupImport, EscKeepsThePanelOnItsMachineAndADamagedBackupIsRefusedInThePrompt) {
    QTemporaryDir dir;
    ControllerBackupWriter backup = ControllerBackupWriter::smallRouter();
    backup.writeTo(QDir(dir.path()).filePath("SYSDISK").toStdString());
    PanelHarness panel;
    bool switched = false;
    panel.window().backupImport().setSwitcher([&switched](const QString&) { switched = true; });
    panel.window().backupImport().importInto(QDir(dir.path()).filePath("SYSDISK"), QDir(dir.path()).filePath("a"));
    EXPECT_TRUE(panel.window().backupImport().importing()); // the panel goes on meanwhile
    ASSERT_TRUE(panel.window().backupImport().waitForImport(30000));
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ESC");
    EXPECT_FALSE(switched);
    EXPECT_TRUE(QFile::exists(QDir(dir.path()).filePath("a/machine.toml")));

    backup.setting[129] = std::nan("");
    backup.writeTo(QDir(dir.path()).filePath("SYSDISK").toStdString());
    panel.window().backupImport().importInto(QDir(dir.path()).filePath("SYSDISK"), QDir(dir.path()).filePath("b"));
    ASSERT_TRUE(panel.window().backupImport().waitForImport(30000));
    ASSERT_TRUE(panel.window().prompt()->active());
    const QString refusal = panel.window().prompt()->question();
    EXPECT_TRUE(refusal.startsWith(QStringLiteral("导入被拒绝:"))) << refusal.toStdString();
    // the reason in the panel's language too (message ids)
    EXPECT_TRUE(refusal.contains(QStringLiteral("SYSDISK/setting: 偏移1032处，参数129（浮动对刀仪厚度）：该值为 NaN；文件已损坏"))) << refusal.toStdString();
    panel.key("ENTER");
    EXPECT_FALSE(switched);
    EXPECT_FALSE(QDir(QDir(dir.path()).filePath("b")).exists());
}

TEST(PanelBackupImport, CancellingAFolderChoiceImportsNothing) {
    QTemporaryDir dir;
    PanelHarness panel;
    QStringList asked;
    chooseFolders(panel, QString(), QDir(dir.path()).filePath("never"), &asked);
    triggerMenuEntry(panel);
    EXPECT_EQ(asked.size(), 1);
    EXPECT_FALSE(panel.window().prompt()->active());
    EXPECT_FALSE(QDir(QDir(dir.path()).filePath("never")).exists());
}

} // namespace m350::test
