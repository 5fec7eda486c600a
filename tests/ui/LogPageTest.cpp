// The 系统日志 page says when the machine folder's system-log.tsv cannot be written, in the panel's
// language, and stops saying it once an entry is written again.
#include "tests/ui/PanelHarness.h"
#include "ui/pages/LogPage.h"
#include "ui/session/LogTail.h"
#include "ui/session/SessionLog.h"

#include <QDir>
#include <QLabel>
#include <QTableWidget>

#include <string>
#include <vector>

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


// A list after each new entry is the newest `most` of everything added, oldest first, and the
// list before it is left as it was (snapshots already sent keep showing what they showed).
TEST(LogTail, HoldsTheNewestEntriesInOrderAndLeavesTheListBeforeAsItWas) {
    for (std::size_t most : {std::size_t{1}, std::size_t{63}, std::size_t{64}, std::size_t{65}, std::size_t{500}}) {
        std::vector<files::LogEntry> all;
        ui::LogTail tail(all, most);
        for (int i = 1; i <= 700; ++i) {
            const ui::LogTail before = tail;
            all.push_back({"2026-11-29 02:00:00", "mdi", "G0 X" + std::to_string(i)});
            tail = tail.with(all.back(), most);
            const std::size_t size = std::min(all.size(), most);
            ASSERT_EQ(tail.size(), size) << most << " " << i;
            ASSERT_EQ(tail.added(), all.size());
            for (std::size_t k = 0; k < size; ++k) {
                ASSERT_EQ(tail[k].detail, all[all.size() - size + k].detail) << most << " " << i << " " << k;
            }
            ASSERT_EQ(before.size(), std::min(all.size() - 1, most));
            if (!before.empty()) {
                ASSERT_EQ(before.back().detail, all[all.size() - 2].detail);
            }
        }
        const ui::LogTail again(all, most); // a log read from its file: the same list
        ASSERT_EQ(again.size(), tail.size());
        std::size_t k = 0;
        for (const files::LogEntry& entry : again) {
            EXPECT_EQ(entry.detail, tail[k++].detail);
        }
    }
}

// While the page is shown, new entries come in on top and the oldest leave at the bottom: the
// rows read as a list filled anew would, the cursor stays on its row and the time column is as
// wide as Qt would fit it.
TEST(LogPage, NewEntriesComeInOnTopWhileThePageIsShown) {
    PanelHarness panel;
    for (int i = 0; i < 10; ++i) {
        panel.key(QStringLiteral("RESET"));
    }
    panel.page(QStringLiteral("log"));
    auto* page = panel.page<ui::LogPage>();
    ASSERT_NE(page, nullptr);
    auto* table = page->findChild<QTableWidget*>();
    ASSERT_NE(table, nullptr);
    for (int i = 0; i < 3; ++i) {
        panel.key(QStringLiteral("DOWN"));
    }
    const int cursor = table->currentRow();
    ASSERT_GT(cursor, 0);
    for (int i = 1; i <= static_cast<int>(ui::SessionLog::kOffered) + 20; ++i) {
        panel.key(QStringLiteral("RESET"));
        if (i % 97 != 0 && i < static_cast<int>(ui::SessionLog::kOffered) + 15) {
            continue;
        }
        const ui::LogEntries log = panel.session().latest()->log;
        ASSERT_EQ(page->rows(), static_cast<int>(log->size()));
        for (int row = 0; row < page->rows(); ++row) {
            const files::LogEntry& entry = (*log)[log->size() - 1 - static_cast<std::size_t>(row)];
            ASSERT_TRUE(page->eventText(row).startsWith(ui::LogPage::eventWords(entry.event))) << i << " " << row;
        }
        EXPECT_EQ(table->currentRow(), cursor);
        const int fitted = table->columnWidth(0); // as Qt fits it to its contents
        table->resizeColumnToContents(0);
        EXPECT_EQ(table->columnWidth(0), fitted);
        EXPECT_GT(fitted, table->fontMetrics().horizontalAdvance(QStringLiteral("2026-11-29 02:00:00")) / 2);
    }
}

} // namespace m350::test
