#pragma once

#include "core/training/Exercise.h"
#include "core/training/Verdict.h"
#include "ui/session/MachineSession.h"
#include "ui/session/PanelSnapshot.h"

#include <QByteArray>
#include <QObject>
#include <QString>
#include <QTemporaryDir>

#include <memory>
#include <optional>
#include <vector>

namespace m350::ui {

class AttemptWriter;
class Language;
class MainWindow;

// One trainee's attempt at an exercise in the panel: the exercise's machine made in a folder of
// its own, the normal panel on it, every action recorded into the chained attempt file as it
// happens, the exercise's faults injected at their times, the task and the time left on the
// message line (in real time; a replayed attempt, on the manual clock, has the faults among its
// actions: ExerciseRun.h's injectFaults, as the headless grader plays them). Handing in (or the time running out) writes the hand-in line and grades the
// machine as it stands with the exercise's checks: the facts the headless grader reads.
class AttemptRun : public QObject {
    Q_OBJECT
public:
    struct Setup {
        training::Exercise exercise;
        QByteArray exerciseToml; // the chain's seed
        QString trainee;
        QString attemptFile;     // where the attempt is recorded
        QByteArray examKey;
        bool hintsAllowed = true; // off in an exam
        MachineSession::Clock clock = MachineSession::Clock::RealTime;
        Language* language = nullptr;
    };
    // Why it could not start, said in the panel's language; else the running attempt.
    static std::unique_ptr<AttemptRun> start(Setup setup, QString* error);
    ~AttemptRun() override;

    MainWindow& window() { return *window_; }
    MachineSession& session() { return *session_; }
    const training::Exercise& exercise() const { return setup_.exercise; }
    const QString& attemptFile() const { return setup_.attemptFile; }
    double timeUsed() const;
    double timeLeft() const { return setup_.exercise.timeLimit - timeUsed(); }
    // The next hint (counted), empty when there is none or hints are off.
    QString takeHint();
    int hintsTaken() const { return hints_; }
    bool handedIn() const { return verdict_.has_value(); }
    // Hands in: the last line, the recording closed, the checks read. Once; again gives the same.
    // `at`: the hand-in's time of a recorded attempt being played, else the session's time now.
    const training::Verdict& handIn(bool timedOut = false, std::optional<double> at = std::nullopt);
    const std::optional<training::Verdict>& verdict() const { return verdict_; }
    QString recordingError() const { return recordingError_; }

signals:
    void timeUp();         // the time limit passed: the caller hands in
    void ticked(double left); // the time left changed by a second or more

private:
    explicit AttemptRun(Setup setup);
    void onSnapshot(const SnapshotPtr& snapshot);
    void injectDueFaults(double now);
    void showNote(double left);

    Setup setup_;
    QTemporaryDir folder_;
    std::unique_ptr<MachineSession> session_;
    std::unique_ptr<MainWindow> window_;
    std::shared_ptr<AttemptWriter> writer_;
    double startDisplay_ = 0.0; // the machine's display time then (the events count from it)
    double now_ = 0.0;
    std::optional<double> firstStart_;
    std::vector<bool> injected_;
    int hints_ = 0;
    int shownSecond_ = -1;
    bool timeUpSent_ = false;
    std::optional<training::Verdict> verdict_;
    QString recordingError_;
};

} // namespace m350::ui
