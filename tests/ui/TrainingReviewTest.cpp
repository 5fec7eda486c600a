// A trainer's review of a recorded attempt (ui/training/ReviewWindow): played to its end at 50x it
// ends where the headless grader ends (every bundled exercise's attempts, check by check); a
// pause stops the attempt's time; '.' steps exactly one block; while O20000 changes the tool the
// program view shows slib-g.nc with the running line highlighted; the trainer's keys never reach
// the trainee's panel; m350-hmi --review renders a moment of the review headless.
#include "tests/ui/PanelHarness.h"
#include "ui/program/CodeView.h"
#include "ui/training/AttemptGrader.h"
#include "ui/training/ReviewBar.h"
#include "ui/training/ReviewPlayback.h"
#include "ui/training/ReviewWindow.h"
#include "ui/training/RunningProgramView.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QKeyEvent>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTimer>
#include <QImage>

#include <gtest/gtest.h>

namespace m350::test {

namespace {

const QString kReviewExercises = QStringLiteral(M350_SOURCE_DIR "/resources/exercises");
const QString kReviewAttempts = QStringLiteral(M350_SOURCE_DIR "/tests/training/attempts");
const QString kPocket = kReviewExercises + QStringLiteral("/pocket-taught-off");
const QString kPocketCorrect = kReviewAttempts + QStringLiteral("/pocket-taught-off/correct.jsonl");

std::unique_ptr<ui::ReviewWindow> openReview(const QString& exercise, const QString& attempt) {
    ui::ReviewWindow::Request request;
    request.exerciseFolder = exercise;
    request.attemptFile = attempt;
    request.language = PanelHarness::language();
    QString error;
    std::unique_ptr<ui::ReviewWindow> review = ui::ReviewWindow::open(request, &error);
    EXPECT_TRUE(review) << error.toStdString();
    if (review) {
        review->resize(1024, 600);
        review->show();
    }
    return review;
}

// Ticks of the bar's timer at `speed` until the attempt has played to its end.
void playToEnd(ui::ReviewWindow& review, int speed) {
    review.bar()->setSpeed(speed);
    for (int tick = 0; tick < 100000 && !review.playback().finished(); ++tick) {
        review.bar()->tick();
    }
}

QString reviewFileLine(const QString& path, int line) {
    const QStringList lines = fileText(path).split(QLatin1Char('\n'));
    return line >= 1 && line <= lines.size() ? lines[line - 1] : QString();
}

} // namespace

TEST(TrainingReview, PlayedAt50xEndsAsTheGradersMachine) {
    for (const QString& name : QDir(kReviewExercises).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QString exercise = kReviewExercises + QLatin1Char('/') + name;
        for (const QString& file :
             QDir(kReviewAttempts + QLatin1Char('/') + name).entryList(QStringList{QStringLiteral("*.jsonl")}, QDir::Files)) {
            const QString attempt = kReviewAttempts + QLatin1Char('/') + name + QLatin1Char('/') + file;
            SCOPED_TRACE((name + QLatin1Char('/') + file).toStdString());
            ui::GradeRequest request;
            request.exerciseFolder = exercise;
            request.attemptFile = attempt;
            request.language = PanelHarness::language();
            const ui::GradeOutcome graded = ui::gradeAttemptFile(request);
            ASSERT_TRUE(graded.verdict) << graded.error.toStdString();

            auto review = openReview(exercise, attempt);
            ASSERT_TRUE(review);
            playToEnd(*review, 50);
            ASSERT_TRUE(review->playback().error().isEmpty()) << review->playback().error().toStdString();
            EXPECT_NEAR(review->playback().now(), review->playback().end(), 1e-6);
            ASSERT_TRUE(review->verdict());
            EXPECT_EQ(review->verdict()->passed, graded.verdict->passed);
            ASSERT_EQ(review->verdict()->checks.size(), graded.verdict->checks.size());
            for (std::size_t i = 0; i < graded.verdict->checks.size(); ++i) {
                const training::CheckResult& mine = review->verdict()->checks[i];
                const training::CheckResult& grader = graded.verdict->checks[i];
                EXPECT_EQ(mine.id, grader.id);
                EXPECT_EQ(mine.passed, grader.passed) << grader.id;
                EXPECT_EQ(mine.measured, grader.measured) << grader.id;
            }
            EXPECT_FALSE(review->playback().nextAction());
            EXPECT_FALSE(review->bar()->playing());
        }
    }
}

TEST(TrainingReview, TheCorrectPocketAttemptEndsWithT2AndTheFixedParameter) {
    auto review = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(review);
    playToEnd(*review, 50);
    const ui::SnapshotPtr end = review->session().latest();
    ASSERT_TRUE(end);
    EXPECT_EQ(end->status.tool, 2);
    EXPECT_NEAR(end->status.parameters.get(831), 110.0, 1e-9);
    EXPECT_FALSE(end->status.alarm);
    EXPECT_TRUE(review->verdict() && review->verdict()->passed);
    EXPECT_EQ(review->bar()->nextText(), review->state().value(QStringLiteral("review_next")).toString());

    // the views lie over the trainee's panel and change nothing it does: under the machine view
    // throughout, the typed 831, 110 and T2 still reach the pages that took them
    auto underMachineView = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(underMachineView);
    underMachineView->setView(ui::ReviewWindow::View::Machine);
    EXPECT_EQ(underMachineView->shown(), QStringLiteral("machine"));
    playToEnd(*underMachineView, 50);
    EXPECT_EQ(underMachineView->session().latest()->status.tool, 2);
    EXPECT_NEAR(underMachineView->session().latest()->status.parameters.get(831), 110.0, 1e-9);
    EXPECT_TRUE(underMachineView->verdict() && underMachineView->verdict()->passed);

    // the wrong attempt crashes into pocket 2's fork, as the grader says
    auto wrong = openReview(kPocket, kReviewAttempts + QStringLiteral("/pocket-taught-off/wrong-no-fix.jsonl"));
    ASSERT_TRUE(wrong);
    playToEnd(*wrong, 50);
    ASSERT_TRUE(wrong->session().latest()->status.alarm);
    EXPECT_EQ(wrong->session().latest()->status.alarm->code, AlarmCode::Crash);
    EXPECT_NE(wrong->session().latest()->status.tool, 2);
}

TEST(TrainingReview, PauseStopsTimeAndTheTimerPlaysAtTheChosenSpeed) {
    auto review = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(review);
    ui::ReviewBar& bar = *review->bar();
    EXPECT_EQ(bar.speed(), 1);
    bar.faster();
    bar.faster();
    EXPECT_EQ(bar.speed(), 5);
    bar.slower();
    EXPECT_EQ(bar.speed(), 2);
    bar.setSpeed(20);
    bar.setPlaying(true);
    QTest::qWait(300);
    const double played = review->playback().now();
    EXPECT_GT(played, 0.0);
    EXPECT_LE(played, 20.0 * 0.3 * 2.0 + 1.0); // no faster than 20x (with room for a slow machine's late ticks)
    bar.setPlaying(false);
    const double paused = review->playback().now();
    QTest::qWait(200);
    EXPECT_EQ(review->playback().now(), paused);
    EXPECT_FALSE(bar.timer()->isActive());
    // one tick at 50x: 50/60 s of the attempt
    bar.setSpeed(50);
    bar.tick();
    EXPECT_NEAR(review->playback().now() - paused, 50.0 / 60.0, 1.0 / 60.0 + 1e-9);
    EXPECT_TRUE(bar.timeText().startsWith(QString::number(review->playback().now(), 'f', 1)));
}

TEST(TrainingReview, StepAdvancesExactlyOneBlock) {
    auto review = openReview(kPocket, kPocketCorrect);
    auto frames = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(review && frames);
    review->playback().play(10.5); // T2 at 10 s: O20000 is changing the tool
    frames->playback().play(10.5);
    const ui::ReviewPlayback::Block before = review->playback().block();
    ASSERT_EQ(before, frames->playback().block());
    EXPECT_EQ(before.file, "slib-g.nc");
    for (int step = 0; step < 3; ++step) {
        const ui::ReviewPlayback::Block from = review->playback().block();
        ASSERT_TRUE(review->playback().stepBlock());
        const ui::ReviewPlayback::Block to = review->playback().block();
        EXPECT_NE(to, from);
        // frame by frame, the block first changes at the same moment, to the same block
        int changes = 0;
        while (frames->playback().block() == from && frames->playback().now() < review->playback().now() + 1.0) {
            frames->playback().play(1.0 / 60.0);
        }
        changes += frames->playback().block() != from;
        EXPECT_EQ(changes, 1);
        EXPECT_NEAR(frames->playback().now(), review->playback().now(), 1e-9);
        EXPECT_EQ(frames->playback().block(), to);
    }
    // the bar's step pauses first, then one block
    review->bar()->setPlaying(true);
    const ui::ReviewPlayback::Block from = review->playback().block();
    review->bar()->step();
    EXPECT_FALSE(review->bar()->playing());
    EXPECT_NE(review->playback().block(), from);
}

TEST(TrainingReview, TheProgramViewHighlightsTheRunningMacroLineDuringAToolChange) {
    auto review = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(review);
    EXPECT_EQ(review->shown(), QStringLiteral("panel")); // nothing runs yet
    review->bar()->setSpeed(50);
    while (review->playback().now() < 15.0) {
        review->bar()->tick();
    }
    const ui::SnapshotPtr now = review->session().latest();
    ASSERT_EQ(now->status.file, "slib-g.nc");
    const int line = static_cast<int>(now->status.line);
    EXPECT_EQ(review->shown(), QStringLiteral("program"));
    ui::RunningProgramView* view = review->programView();
    EXPECT_EQ(view->fileName(), QStringLiteral("slib-g.nc"));
    EXPECT_EQ(view->runningLine(), line);
    ui::CodeView* code = view->code();
    EXPECT_EQ(code->runningLine(), line);
    EXPECT_EQ(code->currentLine(), line); // the editor's cursor follows the run
    // the highlighted row is that line of O20000 in the attempt's slib-g.nc
    bool highlighted = false;
    for (const QTextEdit::ExtraSelection& selection : code->extraSelections()) {
        highlighted = highlighted || selection.cursor.blockNumber() + 1 == line;
    }
    EXPECT_TRUE(highlighted);
    const QString expected = reviewFileLine(QStringLiteral(M350_SOURCE_DIR "/resources/machines/m350-linear16/slib-g.nc"), line);
    EXPECT_FALSE(expected.isEmpty());
    EXPECT_EQ(view->runningText(), expected);
    EXPECT_TRUE(view->captionText().contains(QString::number(line))) << view->captionText().toStdString();
    // the next block moves the highlight with it
    review->bar()->step();
    EXPECT_EQ(code->runningLine(), static_cast<int>(review->session().latest()->status.line));

    // F8: the machine view, then the panel, then following the run again
    review->nextView();
    EXPECT_EQ(review->shown(), QStringLiteral("machine"));
    review->nextView();
    EXPECT_EQ(review->shown(), QStringLiteral("panel"));
    review->nextView();
    EXPECT_EQ(review->shown(), QStringLiteral("program"));
    // once the change is done the panel shows again, the file kept in the view without a line
    while (!review->playback().finished()) {
        review->bar()->tick();
    }
    EXPECT_EQ(review->shown(), QStringLiteral("panel"));
    EXPECT_EQ(code->runningLine(), 0);
}

TEST(TrainingReview, TheReviewKeysWorkAndThePanelKeysDoNotReachTheTraineesPanel) {
    auto review = openReview(kPocket, kPocketCorrect);
    ASSERT_TRUE(review);
    review->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(review.get()));
    const QString page = review->panel().currentPage()->id();
    QTest::keyClick(review.get(), Qt::Key_Plus);
    EXPECT_EQ(review->bar()->speed(), 2);
    QTest::keyClick(review.get(), Qt::Key_Minus);
    EXPECT_EQ(review->bar()->speed(), 1);
    QTest::keyClick(review.get(), Qt::Key_Space);
    EXPECT_TRUE(review->bar()->playing());
    QTest::keyClick(review.get(), Qt::Key_Space);
    EXPECT_FALSE(review->bar()->playing());
    QTest::keyClick(review.get(), Qt::Key_F8);
    EXPECT_EQ(review->view(), ui::ReviewWindow::View::Machine);
    // F9 (START), Ctrl+D (the MDI page), F1 and typing stop at the review
    QTest::keyClick(review.get(), Qt::Key_F9);
    QTest::keyClick(review.get(), Qt::Key_D, Qt::ControlModifier);
    QTest::keyClick(review.get(), Qt::Key_F1);
    QTest::keyClicks(review.get(), QStringLiteral("G0X5"));
    ui::settle(review->session());
    EXPECT_EQ(review->panel().currentPage()->id(), page);
    EXPECT_EQ(review->session().latest()->status.run, controller::PanelStatus::Run::Idle);
    // '.' steps: the attempt's own T2 at 10 s is the first block
    QTest::keyClick(review.get(), Qt::Key_Period);
    EXPECT_GE(review->playback().now(), 10.0);
    EXPECT_FALSE(review->playback().block().file.empty());
}

namespace {

struct ReviewRun {
    int exitCode = -1;
    QString err;
    QJsonObject state;
};

ReviewRun runReview(const QStringList& arguments, const QString& state) {
    QProcess hmi;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    hmi.setProcessEnvironment(env);
    hmi.start(QStringLiteral(M350_HMI_PATH), arguments);
    ReviewRun run;
    if (!hmi.waitForFinished(120000)) {
        hmi.kill();
        run.err = QStringLiteral("m350-hmi did not finish");
        return run;
    }
    run.exitCode = hmi.exitCode();
    run.err = QString::fromUtf8(hmi.readAllStandardError());
    run.state = QJsonDocument::fromJson(fileText(state).toUtf8()).object();
    return run;
}

} // namespace

TEST(TrainingReview, TheCommandLineRendersAMomentOfTheReview) {
    QTemporaryDir dir;
    const QString state = dir.filePath(QStringLiteral("state.json"));
    const QString shot = dir.filePath(QStringLiteral("review.png"));
    ReviewRun run = runReview({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--review"), kPocketCorrect,
                               QStringLiteral("--exercise"), kPocket, QStringLiteral("--review-until"), QStringLiteral("15"),
                               QStringLiteral("--state"), state, QStringLiteral("--screenshot"), shot},
                              state);
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_NEAR(run.state.value(QStringLiteral("review_time")).toDouble(), 15.0, 1e-6);
    EXPECT_EQ(run.state.value(QStringLiteral("review_shown")).toString(), QStringLiteral("program"));
    EXPECT_EQ(run.state.value(QStringLiteral("running_file")).toString(), QStringLiteral("slib-g.nc"));
    EXPECT_GT(run.state.value(QStringLiteral("running_line")).toInt(), 0);
    EXPECT_EQ(run.state.value(QStringLiteral("review_next")).toString(), QStringLiteral("Next: 60.0 s hand in"));
    EXPECT_FALSE(QImage(shot).isNull());

    // to its end: the grader's verdict
    run = runReview({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--review"), kPocketCorrect,
                     QStringLiteral("--exercise"), kPocket, QStringLiteral("--state"), state},
                    state);
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(run.state.value(QStringLiteral("passed")).toBool());
    EXPECT_EQ(run.state.value(QStringLiteral("review_next")).toString(), QStringLiteral("Handed in: passed"));

    // an attempt at another exercise, and a screenshot over the attempt, are refused: exit 2
    run = runReview({QStringLiteral("--review"), kPocketCorrect, QStringLiteral("--exercise"),
                     kReviewExercises + QStringLiteral("/floating-setter"), QStringLiteral("--state"), state},
                    state);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("pocket-taught-off"))) << run.err.toStdString();
    const QString copy = dir.filePath(QStringLiteral("attempt.png"));
    ASSERT_TRUE(QFile::copy(kPocketCorrect, copy));
    run = runReview({QStringLiteral("--review"), copy, QStringLiteral("--exercise"), kPocket, QStringLiteral("--screenshot"), copy},
                    state);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(fileText(copy), fileText(kPocketCorrect));
}

} // namespace m350::test
