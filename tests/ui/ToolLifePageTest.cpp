// 刀具寿命 through the operator's path on the default M350 (where tool life management is a
// simulator extra): the 刀具表 page's Shift+F1 opens it, runs of a program using group 1 until its
// first tool's life is over bring in the sister, which the view marks in use and highlights; the
// group's reset asks first and lands in toollife.txt.
#include "PanelHarness.h"

#include "core/tools/ToolLifeFile.h"
#include "ui/pages/ToolLifePage.h"
#include "ui/pages/ToolTablePage.h"
#include "ui/panel/PromptBox.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <QTemporaryDir>

namespace m350::test {

namespace {

using Column = ui::ToolLifePage::Column;
using Run = controller::PanelStatus::Run;

// Group 1: T3 then T4, two uses each; group 2: T5, 1 minute.
constexpr const char* kGroups = "group 1 life 2 count\ntool 3 h 3 d 0 used 0\ntool 4 h 4 d 0 used 0\n"
                                "group 2 life 1 minutes\ntool 5 h 5 d 0 used 3\n";

QString machineWithGroups(QTemporaryDir& dir) {
    QString error;
    auto copy = ui::copyBundledMachine(dir.path(), &error);
    EXPECT_TRUE(copy) << error.toStdString();
    putFile(QDir(*copy).filePath(tools::kToolLifeFile), kGroups);
    return copy.value_or(QString());
}

void runOnce(PanelHarness& panel) {
    panel.key("START");
    for (int second = 0; second < 120 && panel.session().latest()->status.run != Run::Finished; ++second) {
        panel.advance(1.0);
    }
    ASSERT_EQ(panel.session().latest()->status.run, Run::Finished) << panel.session().latest()->lastError.toStdString();
}

ui::ToolLifePage* openLife(PanelHarness& panel) {
    panel.key("PROBE");
    panel.softkey(2); // 刀具表
    EXPECT_NE(panel.page<ui::ToolTablePage>(), nullptr);
    const QString label = panel.window().state()["softkeys"].toArray().at(6).toString();
    EXPECT_TRUE(label.endsWith(QStringLiteral("刀具寿命"))) << label.toStdString() << ": the second row's first key";
    panel.softkey(7); // Shift+F1 刀具寿命
    return panel.page<ui::ToolLifePage>();
}

} // namespace

TEST(ToolLifePage, TheToolTableOpensItAndItShowsTheGroupsAndTheSimulatorExtraNote) {
    QTemporaryDir dir;
    PanelHarness panel(machineWithGroups(dir));
    ui::ToolLifePage* page = openLife(panel);
    ASSERT_NE(page, nullptr);
    ASSERT_EQ(page->rowCount(), 3);
    EXPECT_EQ(page->cellText(0, Column::Group), "1");
    EXPECT_EQ(page->cellText(0, Column::Tool), "T3");
    EXPECT_EQ(page->cellText(1, Column::Group), "") << "a group's number is on its first tool's row";
    EXPECT_EQ(page->cellText(1, Column::Tool), "T4");
    EXPECT_EQ(page->cellText(2, Column::Life), "1:00");
    EXPECT_EQ(page->cellText(2, Column::Used), "0:12") << "3 units of 4 s";
    EXPECT_EQ(page->cellText(2, Column::Remaining), "0:48");
    EXPECT_EQ(page->cellText(0, Column::Remaining), "2");
    EXPECT_FALSE(page->rowHighlighted(0));
    auto* note = page->findChild<QLabel*>("toolLifeNote");
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->text().contains(QStringLiteral("模拟器扩展"))) << note->text().toStdString();
    EXPECT_TRUE(note->text().contains(QStringLiteral("T101"))) << note->text().toStdString();
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), QStringLiteral("tools"));
}

TEST(ToolLifePage, AProgramUsingTheGroupUntilItsLifeIsOverBringsInTheSister) {
    QTemporaryDir dir;
    const QString folder = machineWithGroups(dir);
    PanelHarness panel(folder);
    panel.loadProgram("life.nc", "T101\nM30\n"); // one use of group 1 a run
    for (int run = 0; run < 3; ++run) {
        runOnce(panel);
    }
    EXPECT_EQ(panel.session().latest()->status.tool, 4) << "T3 served two runs, the third took its sister";
    ui::ToolLifePage* page = openLife(panel);
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(page->cellText(0, Column::Used), "2");
    EXPECT_EQ(page->cellText(0, Column::Remaining), "0");
    EXPECT_TRUE(page->cellText(0, Column::State).startsWith('#')) << page->cellText(0, Column::State).toStdString();
    EXPECT_FALSE(page->rowHighlighted(0));
    EXPECT_TRUE(page->cellText(1, Column::State).startsWith('@')) << page->cellText(1, Column::State).toStdString();
    EXPECT_TRUE(page->rowHighlighted(1)) << "the sister in use";
    EXPECT_EQ(page->cellText(1, Column::Used), "1");
    EXPECT_TRUE(page->headerText().contains(QStringLiteral("T4"))) << page->headerText().toStdString();
    EXPECT_TRUE(fileText(QDir(folder).filePath(tools::kToolLifeFile))
                    .contains(QStringLiteral("tool 3 h 3 d 0 used 2\ntool 4 h 4 d 0 used 1\n")))
        << "the session saves what the runs counted";
}

TEST(ToolLifePage, ResetAsksFirstThenClearsTheGroupInToolLifeTxt) {
    QTemporaryDir dir;
    const QString folder = machineWithGroups(dir);
    PanelHarness panel(folder);
    panel.loadProgram("life.nc", "T101\nM30\n");
    runOnce(panel);
    runOnce(panel);
    ui::ToolLifePage* page = openLife(panel);
    ASSERT_NE(page, nullptr);
    ASSERT_EQ(page->cellText(0, Column::Used), "2");
    panel.softkey(1); // 寿命清零
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().prompt()->question().contains('1')) << panel.window().prompt()->question().toStdString();
    panel.key("ESC"); // no: nothing changes
    EXPECT_EQ(page->cellText(0, Column::Used), "2");
    panel.key("DOWN");
    panel.key("DOWN"); // T5: group 2
    EXPECT_EQ(page->selectedGroup(), 2);
    panel.key("UP");
    EXPECT_EQ(page->selectedGroup(), 1);
    panel.softkey(1);
    panel.key("ENTER");
    EXPECT_EQ(page->cellText(0, Column::Used), "0");
    EXPECT_EQ(page->cellText(0, Column::Remaining), "2");
    EXPECT_EQ(page->cellText(2, Column::Used), "0:12") << "group 2 keeps its time";
    const QString saved = fileText(QDir(folder).filePath(tools::kToolLifeFile));
    EXPECT_TRUE(saved.contains(QStringLiteral("tool 3 h 3 d 0 used 0\n"))) << saved.toStdString();
    EXPECT_TRUE(saved.contains(QStringLiteral("tool 5 h 5 d 0 used 3\n"))) << saved.toStdString();
}

} // namespace m350::test
