// 训练 Training's window driven through its keys (the offscreen platform, the manual clock): the
// start page, an attempt's panel with its note, hints counted, hand-in and the verdict page, F5
// opening a failed check's parameter, the progress kept, and an exam (no hints, time running out).
#include "tests/ui/PanelHarness.h"

#include "core/training/Exam.h"
#include "ui/pages/PageId.h"
#include "ui/pages/ParamPage.h"
#include "ui/panel/MainWindow.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/replay/Replay.h"
#include "ui/training/AttemptRun.h"
#include "ui/training/TrainingStartPage.h"
#include "ui/training/TrainingWindow.h"
#include "ui/training/VerdictPage.h"

#include <QDir>
#include <QFile>
#include <QTableWidget>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace m350::test {

namespace {

// A training on a folder holding only pocket-taught-off, in English.
struct TrainingHarness {
    explicit TrainingHarness(std::optional<training::Exam> exam = std::nullopt) {
        const QString exercises = dir.filePath(QStringLiteral("exercises/pocket-taught-off"));
        QDir().mkpath(exercises);
        EXPECT_TRUE(QFile::copy(QStringLiteral(M350_SOURCE_DIR "/resources/exercises/pocket-taught-off/exercise.toml"),
                                exercises + QStringLiteral("/exercise.toml")));
        ui::TrainingWindow::Options options;
        options.exercisesFolder = dir.filePath(QStringLiteral("exercises"));
        options.attemptsFolder = dir.filePath(QStringLiteral("attempts"));
        QDir().mkpath(options.attemptsFolder);
        options.trainee = QStringLiteral("王伟");
        options.exam = std::move(exam);
        options.clock = ui::MachineSession::Clock::Manual;
        options.language = PanelHarness::language();
        window = std::make_unique<ui::TrainingWindow>(options);
        window->show();
    }
    EnglishPanel english;
    QTemporaryDir dir;
    std::unique_ptr<ui::TrainingWindow> window;
};

} // namespace

TEST(TrainingWindow, AnAttemptFromStartToVerdictThroughTheKeys) {
    TrainingHarness training;
    ui::TrainingWindow& w = *training.window;
    ASSERT_EQ(w.exercises().size(), 1u);
    EXPECT_EQ(w.pageId(), QStringLiteral("training"));
    EXPECT_EQ(w.startPage()->table()->item(0, 2)->text(), QStringLiteral("not tried"));
    EXPECT_TRUE(w.startPage()->text().contains(QStringLiteral("Find the wrong parameter")));
    EXPECT_FALSE(w.softkeys()->enabled(3)) << "no hint before an attempt";

    w.softkey(1);
    ASSERT_TRUE(w.attempt()) << w.startPage()->text().toStdString();
    EXPECT_EQ(w.pageId(), QStringLiteral("attempt"));
    ui::settle(w.attempt()->session());
    EXPECT_TRUE(w.attempt()->window().messageText().contains(QStringLiteral("A pocket taught 2 mm off")))
        << w.attempt()->window().messageText().toStdString();
    EXPECT_TRUE(w.attempt()->window().messageText().contains(QStringLiteral("time left 10:00")));

    w.key(QStringLiteral("TRAINING"));
    EXPECT_EQ(w.pageId(), QStringLiteral("training"));
    w.softkey(3);
    EXPECT_TRUE(w.startPage()->text().startsWith(QStringLiteral("Hint 1: "))) << w.startPage()->text().toStdString();
    w.softkey(3);
    w.softkey(3);
    EXPECT_EQ(w.startPage()->text(), QStringLiteral("No more hints for this exercise."));
    EXPECT_EQ(w.attempt()->hintsTaken(), 2);

    w.key(QStringLiteral("TRAINING"));
    EXPECT_EQ(w.pageId(), QStringLiteral("attempt"));
    w.key(QStringLiteral("TRAINING"));
    w.softkey(4);
    EXPECT_EQ(w.pageId(), QStringLiteral("verdict"));
    ASSERT_TRUE(w.attempt()->verdict());
    EXPECT_FALSE(w.attempt()->verdict()->passed);
    EXPECT_EQ(w.attempt()->verdict()->hintsUsed, 2);
    EXPECT_TRUE(w.verdictPage()->summary().startsWith(QStringLiteral("FAILED: A pocket taught 2 mm off")));
    // the first failed check is selected: pocket 2's X, parameter 831
    EXPECT_EQ(w.verdictPage()->target().kind, training::CheckTarget::Kind::Parameter);
    EXPECT_EQ(w.verdictPage()->target().number, 831);
    w.softkey(5);
    EXPECT_EQ(w.pageId(), QStringLiteral("attempt"));
    EXPECT_EQ(w.attempt()->window().currentPage()->id(), QStringLiteral("param"));
    auto* param = dynamic_cast<ui::ParamPage*>(w.attempt()->window().page(ui::PageId::param));
    ASSERT_TRUE(param);
    EXPECT_EQ(param->selectedNumber(), 831);

    w.key(QStringLiteral("TRAINING"));
    EXPECT_EQ(w.pageId(), QStringLiteral("verdict"));
    w.softkey(6);
    EXPECT_EQ(w.startPage()->table()->item(0, 2)->text(), QStringLiteral("failed (1 tries)"));
    QFile progress(training.dir.filePath(QStringLiteral("attempts/progress.json")));
    ASSERT_TRUE(progress.open(QIODevice::ReadOnly));
    EXPECT_TRUE(progress.readAll().contains("\"tries\": 1"));
}

TEST(TrainingWindow, AFailedChecksMacroLineOpensInTheEditor) {
    TrainingHarness training;
    ui::TrainingWindow& w = *training.window;
    w.softkey(1);
    ASSERT_TRUE(w.attempt());
    // T2 run with pocket 2's X left 2 mm off: the empty nose lands on T2's holder in O20000
    ui::OperatorAction mdi = ui::OperatorAction::key(QStringLiteral("MDI"));
    mdi.t = 1;
    ui::OperatorAction t2 = ui::OperatorAction::typed(QStringLiteral("T2"));
    t2.t = 2;
    ui::OperatorAction enter = ui::OperatorAction::key(QStringLiteral("ENTER"));
    enter.t = 2.5;
    ui::OperatorAction run = ui::OperatorAction::softkeyPress(1);
    run.t = 3;
    ui::OperatorAction wait;
    wait.t = 40;
    ASSERT_TRUE(ui::playReplay(w.attempt()->window(), w.attempt()->session(), {mdi, t2, enter, run, wait}).isEmpty());
    w.key(QStringLiteral("TRAINING"));
    w.softkey(4);
    ASSERT_EQ(w.pageId(), QStringLiteral("verdict"));
    w.key(QStringLiteral("DOWN")); // pocket-2-x, then no-crash
    ASSERT_EQ(w.verdictPage()->target().kind, training::CheckTarget::Kind::Line);
    EXPECT_EQ(w.verdictPage()->target().file, "slib-g.nc");
    const int line = w.verdictPage()->target().line;
    EXPECT_GT(line, 0);
    w.softkey(5);
    EXPECT_EQ(w.pageId(), QStringLiteral("attempt"));
    EXPECT_EQ(w.attempt()->window().currentPage()->id(), QStringLiteral("program"));
    const QJsonObject program = w.attempt()->window().currentPage()->state();
    EXPECT_EQ(program.value(QStringLiteral("editor_file")).toString(), QStringLiteral("slib-g.nc"));
    EXPECT_EQ(program.value(QStringLiteral("editor_line")).toInt(), line);
}

TEST(TrainingWindow, AnExamHasNoHintsAndHandsInWhenTheTimeRunsOut) {
    training::Exam exam;
    exam.exercises = {"pocket-taught-off"};
    exam.timeLimit = 5.0;
    exam.key = "secret";
    TrainingHarness training(exam);
    ui::TrainingWindow& w = *training.window;
    w.softkey(1);
    ASSERT_TRUE(w.attempt());
    w.key(QStringLiteral("TRAINING"));
    EXPECT_FALSE(w.softkeys()->enabled(3));
    w.softkey(3);
    EXPECT_EQ(w.attempt()->hintsTaken(), 0);
    w.key(QStringLiteral("TRAINING"));
    for (int frame = 0; frame < 6 * 60 && !w.attempt()->handedIn(); ++frame) {
        w.attempt()->session().advance(1.0 / 60.0);
        ui::settle(w.attempt()->session());
    }
    ASSERT_TRUE(w.attempt()->handedIn()) << "the time ran out";
    EXPECT_EQ(w.pageId(), QStringLiteral("verdict"));
    EXPECT_TRUE(w.attempt()->verdict()->timedOut);
    EXPECT_FALSE(w.attempt()->verdict()->passed);
    EXPECT_TRUE(w.verdictPage()->summary().contains(QStringLiteral("time out")));
}

} // namespace m350::test
