// The 系统日志 page says when the machine folder's system-log.tsv cannot be written, in the panel's
// language, and stops saying it once an entry is written again.
#include "tests/ui/PanelHarness.h"
#include "ui/pages/LogPage.h"
#include "ui/session/SessionLog.h"

#include <QDir>
#include <QLabel>

namespace m350::test {

namespace {

QString logProblemShown(PanelHarness& panel) {
    panel.page(QStringLiteral("log"));
    auto* label = panel.window().findChild<QLabel*>(QStringLiteral("logProblem"));
    return label && label->isVisible() ? label->text() : QString();
}

} // namespace

TEST(LogPage, AnUnwritableSystemLogIsSaidOnThePageInThePanelsLanguage) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    const QString log = QDir(*folder).filePath(QStringLiteral("system-log.tsv"));
    QFile::remove(log);
    ASSERT_TRUE(QDir().mkpath(log)); // a folder where the log file goes: nothing can be appended
    {
        PanelHarness panel(*folder);
        panel.key(QStringLiteral("RESET")); // an entry the log cannot take
        const QString zh = logProblemShown(panel);
        EXPECT_TRUE(zh.startsWith(QStringLiteral("系统日志未保存"))) << zh.toStdString();
        EXPECT_TRUE(zh.contains(QStringLiteral("system-log.tsv"))) << zh.toStdString();
        EnglishPanel english;
        const QString en = logProblemShown(panel);
        EXPECT_TRUE(en.startsWith(QStringLiteral("The System Log is not saved: "))) << en.toStdString();
        EXPECT_EQ(panel.page<ui::LogPage>()->state().value("log_problem").toString(), en);
    }
    ASSERT_TRUE(QDir(log).removeRecursively()); // room again: the next entry is written
    PanelHarness again(*folder);
    again.key(QStringLiteral("RESET"));
    EXPECT_EQ(logProblemShown(again), QString());
}

// The page shows the newest SessionLog::kOffered entries, newest first; the file keeps them all
// (snapshots carry only what the page shows: a copy of the whole log at every entry made a long
// session slow).
TEST(LogPage, ShowsTheNewestEntriesWhileTheFileKeepsThemAll) {
    QTemporaryDir dir;
    const std::string folder = dir.path().toStdString();
    const int count = static_cast<int>(ui::SessionLog::kOffered) + 40;
    {
        ui::SessionLog log(folder);
        for (int i = 1; i <= count; ++i) {
            log.record("mdi", QStringLiteral("G0 X%1").arg(i));
        }
        ASSERT_EQ(log.entries()->size(), ui::SessionLog::kOffered);
        EXPECT_EQ(log.entries()->back().detail, "G0 X" + std::to_string(count));
        EXPECT_EQ(log.entries()->front().detail, "G0 X41");
    }
    ui::SessionLog again(folder); // the file has every entry, the snapshot the newest
    EXPECT_EQ(again.entries()->size(), ui::SessionLog::kOffered);
    EXPECT_EQ(fileText(dir.filePath(QStringLiteral("system-log.tsv"))).count(QStringLiteral("G0 X")), count);

    PanelHarness panel;
    for (int i = 1; i <= count; ++i) {
        panel.key(QStringLiteral("RESET"));
    }
    panel.page(QStringLiteral("log"));
    auto* page = panel.page<ui::LogPage>();
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(page->rows(), static_cast<int>(ui::SessionLog::kOffered));
}

} // namespace m350::test
