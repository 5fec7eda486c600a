#pragma once

#include "core/training/Exercise.h"
#include "core/training/Verdict.h"
#include "ui/session/PanelSnapshot.h"
#include "ui/training/AttemptFile.h"

#include <QByteArray>
#include <QJsonObject>
#include <QMainWindow>
#include <QTemporaryDir>

#include <memory>
#include <optional>


namespace m350::ui {

class Language;
class MachineSession;
class MachineView;
class MainWindow;
class ReviewBar;
class ReviewPlayback;
class RunningProgramView;

// A trainer's review of a recorded attempt (m350-hmi --review A.jsonl --exercise DIR): the
// exercise's machine made afresh, as the grader makes it, with the normal panel on it showing what
// the trainee saw, and the review bar under it (ReviewBar: 1x-50x, pause, one block at a time).
// The attempt plays with the exercise's faults, as the grader plays it, so the machine ends as the
// grader's does; the verdict is read at the end. The panel is the trainee's: the trainer's keys
// and clicks do not reach it (a page the trainer opened would take the trainee's next softkey).
// F8 switches the view: following the run (the running program, its line highlighted, while a
// block runs; the panel otherwise), the machine view (图形显示, the run's progress), the panel.
class ReviewWindow : public QMainWindow {
    Q_OBJECT
public:
    struct Request {
        QString exerciseFolder;
        QString attemptFile;
        QByteArray examKey; // an exam's attempt is chained with the exam's key
        Language* language = nullptr;
    };
    // Why the review cannot open (file:line:col and what, in the panel's language), else the window.
    static std::unique_ptr<ReviewWindow> open(const Request& request, QString* error);
    ~ReviewWindow() override;

    enum class View { Follow, Machine, Panel };
    View view() const { return view_; }
    void setView(View view);
    void nextView(); // F8: Follow -> Machine -> Panel -> Follow
    // What is on screen now: "program", "machine" or "panel".
    QString shown() const;

    MainWindow& panel() { return *panel_; }
    MachineSession& session() { return *session_; }
    ReviewPlayback& playback() { return *playback_; }
    ReviewBar* bar() const { return bar_; }
    RunningProgramView* programView() const { return program_; }
    MachineView* machineView() const { return machine_; }
    const training::Exercise& exercise() const { return exercise_; }
    // The verdict on the machine once the attempt has played to its end (nullopt before).
    const std::optional<training::Verdict>& verdict() const { return verdict_; }
    // The views follow the latest snapshot (after each tick or step; the bar calls it).
    void follow();
    QJsonObject state() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    ReviewWindow(training::Exercise exercise, Attempt attempt, Language* language);
    void retranslate();
    void showOver(QWidget* view); // nullptr: the panel
    QString viewName() const;
    MessageLanguage spokenLanguage() const;

    training::Exercise exercise_;
    Attempt attempt_;
    Language* language_;
    QTemporaryDir folder_;
    QString machineFolder_;
    std::unique_ptr<MachineSession> session_;
    std::unique_ptr<MainWindow> panel_;
    std::unique_ptr<ReviewPlayback> playback_;
    QWidget* screen_ = nullptr; // the panel, the program view or the machine view over it
    RunningProgramView* program_ = nullptr;
    MachineView* machine_ = nullptr;
    ReviewBar* bar_ = nullptr;
    View view_ = View::Follow;
    double startDisplay_ = 0.0;
    std::optional<training::Verdict> verdict_;
};

} // namespace m350::ui
