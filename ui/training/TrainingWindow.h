#pragma once

#include "core/training/Exam.h"
#include "core/training/Exercise.h"
#include "ui/session/MachineSession.h"
#include "ui/training/TrainingProgress.h"

#include <QJsonObject>
#include <QMainWindow>

#include <memory>
#include <optional>
#include <vector>

class QStackedWidget;
class QVBoxLayout;

namespace m350::ui {

class AttemptRun;
class Language;
class SoftkeyBar;
class TrainingStartPage;
class VerdictPage;

// 训练 Training (m350-hmi --training): the start page lists the exercises; F1 starts the selected
// one on a machine of its own with the normal panel (every page, the machine view), recorded as a
// chained attempt; F7 comes back here during the attempt for F2 the task, F3 a hint (counted, off
// in an exam) and F4 hand in; the time running out hands in. The verdict page follows: each check
// with its explanation, F5 opening a failed check's parameter or macro line in the panel.
class TrainingWindow : public QMainWindow {
    Q_OBJECT
public:
    struct Options {
        QString exercisesFolder;
        QString attemptsFolder; // attempts and progress.json
        QString trainee;
        std::optional<training::Exam> exam;
        MachineSession::Clock clock = MachineSession::Clock::RealTime;
        Language* language = nullptr;
    };
    explicit TrainingWindow(Options options, QWidget* parent = nullptr);
    ~TrainingWindow() override;

    // The training's keys: softkeys 1-6 on its pages, UP / DOWN, and F7 (TRAINING) between the
    // attempt's panel and this page. The keyboard's F1-F6, arrows and F7 come here too.
    void softkey(int number);
    void key(const QString& name);

    // Hands the attempt in (F4); `at`: the hand-in's time when a recorded attempt is played (its
    // last line's `t`), else the session's time now.
    void handIn(bool timedOut, std::optional<double> at = std::nullopt);
    QString pageId() const; // "training", "attempt", "verdict"
    AttemptRun* attempt() const { return attempt_.get(); }
    TrainingStartPage* startPage() const { return start_; }
    VerdictPage* verdictPage() const { return verdict_; }
    SoftkeyBar* softkeys() const { return softkeys_; }
    const std::vector<training::Exercise>& exercises() const { return exercises_; }
    // Exercises that did not load (file:line:col and why), shown on the start page.
    const QStringList& problems() const { return problems_; }
    QJsonObject state() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void loadExercises();
    void refreshStart();
    void refreshSoftkeys();
    void startSelected();
    void openTarget();
    void showPage(QWidget* page);
    MessageLanguage language() const;
    QString attemptPath(const training::Exercise& exercise) const;

    Options options_;
    std::vector<training::Exercise> exercises_;
    QStringList problems_;
    TrainingProgress progress_;
    QStackedWidget* stack_;
    TrainingStartPage* start_;
    QWidget* attemptHolder_;
    QVBoxLayout* attemptLayout_;
    VerdictPage* verdict_;
    SoftkeyBar* softkeys_;
    std::unique_ptr<AttemptRun> attempt_;
    int attemptExercise_ = -1;
};

} // namespace m350::ui
