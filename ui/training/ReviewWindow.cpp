#include "core/training/FactsFromController.h"
#include "ui/training/ReviewWindow.h"

#include "core/config/CallCodeParameters.h"
#include "core/config/MachineConfig.h"
#include "core/files/ScratchFolder.h"
#include "ui/i18n/Language.h"
#include "ui/pages/GraphicsPage.h"
#include "ui/panel/MainWindow.h"
#include "ui/session/MachineSession.h"
#include "ui/training/AttemptGrader.h"
#include "ui/training/ExerciseRun.h"
#include "ui/training/ReviewBar.h"
#include "ui/training/ReviewPlayback.h"
#include "ui/training/RunningProgramView.h"
#include "ui/view/MachineView.h"

#include <QApplication>
#include <QEvent>
#include <QJsonArray>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QMenu>
#include <QGridLayout>
#include <QStringList>
#include <QVBoxLayout>

#include <variant>

namespace m350::ui {

namespace {

bool inRun(const PanelSnapshot& snapshot) {
    using Run = controller::PanelStatus::Run;
    const controller::PanelStatus& s = snapshot.status;
    return s.line > 0 && !s.file.empty() && s.run != Run::Idle && s.run != Run::Finished;
}

} // namespace

ReviewWindow::ReviewWindow(training::Exercise exercise, Attempt attempt, Language* language)
    : exercise_(std::move(exercise)), attempt_(std::move(attempt)), language_(language) {}

ReviewWindow::~ReviewWindow() {
    qApp->removeEventFilter(this);
    if (bar_) {
        bar_->setPlaying(false);
    }
    playback_.reset();
    panel_.reset();
    session_.reset();
}

std::unique_ptr<ReviewWindow> ReviewWindow::open(const Request& request, QString* error) {
    GradeRequest read;
    read.exerciseFolder = request.exerciseFolder;
    read.attemptFile = request.attemptFile;
    read.examKey = request.examKey;
    read.language = request.language;
    std::optional<AttemptAtExercise> found = readAttemptAtExercise(read, error);
    if (!found) {
        return nullptr;
    }
    std::unique_ptr<ReviewWindow> window(new ReviewWindow(std::move(found->exercise), std::move(found->attempt), request.language));
    ReviewWindow& w = *window;
    const MessageLanguage language = spokenBy(request.language);
    if (!w.folder_.isValid()) {
        *error = tr("no folder for the attempt's machine: %1").arg(w.folder_.errorString());
        return nullptr;
    }
    files::setScratchFolder(w.folder_.path().toStdString()); // thrown away with the review: nothing there is synced
    w.machineFolder_ = w.folder_.filePath(QStringLiteral("machine"));
    if (auto why = prepareAttemptMachine(w.exercise_, w.machineFolder_)) {
        *error = QString::fromStdString(why->in(language));
        return nullptr;
    }
    auto loaded = config::loadMachineFolder(w.machineFolder_.toStdString());
    if (auto* failed = std::get_if<config::ConfigError>(&loaded)) {
        *error = QString::fromStdString(failed->where() + ": " + failed->message.in(language));
        return nullptr;
    }
    config::MachineConfig& config = std::get<config::MachineConfig>(loaded);
    const gcode::Dialect dialect = config::parsingDialect(config);
    // the manual clock: the review's own pace moves the machine, in the grader's frames
    w.session_ = std::make_unique<MachineSession>(std::move(config),
                                                  attemptSessionOptions(w.exercise_, MachineSession::Clock::Manual));
    w.panel_ = std::make_unique<MainWindow>(*w.session_, w.machineFolder_, request.language);

    auto* central = new QWidget(&w);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    // the views lie over the panel, which is never hidden: a page acts on what it shows (the MDI
    // page takes typed text only while its editor is visible), as it did for the trainee
    w.screen_ = new QWidget(central);
    auto* layers = new QGridLayout(w.screen_);
    layers->setContentsMargins(0, 0, 0, 0);
    layers->addWidget(w.panel_.get(), 0, 0);
    w.program_ = new RunningProgramView(dialect, w.machineFolder_, w.screen_);
    layers->addWidget(w.program_, 0, 0);
    w.machine_ = new MachineView(w.screen_);
    w.machine_->setAutoFillBackground(true);
    layers->addWidget(w.machine_, 0, 0);
    w.program_->hide();
    w.machine_->hide();
    column->addWidget(w.screen_, 1);
    w.setCentralWidget(central);

    settle(*w.session_);
    w.session_->examine([&w](controller::Controller& controller) { w.startDisplay_ = training::attemptClock(controller); });
    std::vector<ReplayPlace> places;
    std::vector<OperatorAction> actions = gradedActions(w.exercise_, w.attempt_, &places);
    w.playback_ = std::make_unique<ReviewPlayback>(*w.panel_, *w.session_, std::move(actions), std::move(places),
                                                   request.attemptFile);
    w.bar_ = new ReviewBar(*w.playback_, central);
    column->addWidget(w.bar_);
    connect(w.bar_, &ReviewBar::played, &w, &ReviewWindow::follow);
    connect(w.bar_, &ReviewBar::viewRequested, &w, &ReviewWindow::nextView);
    qApp->installEventFilter(&w); // after the panel's: the review's filter is asked first
    w.retranslate();
    w.follow();
    return window;
}

void ReviewWindow::setView(View view) {
    view_ = view;
    follow();
    retranslate();
}

void ReviewWindow::nextView() {
    setView(view_ == View::Follow ? View::Machine : view_ == View::Machine ? View::Panel : View::Follow);
}

QString ReviewWindow::shown() const {
    return !program_->isHidden() ? QStringLiteral("program") : !machine_->isHidden() ? QStringLiteral("machine") : QStringLiteral("panel");
}

void ReviewWindow::showOver(QWidget* view) {
    for (QWidget* over : {static_cast<QWidget*>(program_), static_cast<QWidget*>(machine_)}) {
        if (over != view && !over->isHidden()) {
            over->hide();
        }
    }
    if (view && view->isHidden()) {
        view->show();
        view->raise();
    }
}

void ReviewWindow::follow() {
    const SnapshotPtr snapshot = session_->latest();
    if (!snapshot) {
        return;
    }
    program_->render(*snapshot);
    QWidget* show = nullptr;
    if (view_ == View::Machine) {
        show = machine_;
    } else if (view_ == View::Follow && inRun(*snapshot)) {
        show = program_;
    }
    if (show == machine_) {
        machine_->setContent(GraphicsPage::contentOf(*snapshot));
    }
    showOver(show);
    if (playback_->finished() && !verdict_ && playback_->error().isEmpty()) {
        verdict_ = gradePlayedAttempt(*session_, exercise_, attempt_, startDisplay_, machineFolder_);
        retranslate();
    }
}

MessageLanguage ReviewWindow::spokenLanguage() const { return spokenBy(language_); }

QString ReviewWindow::viewName() const {
    switch (view_) {
    case View::Follow: return tr("Follow the run");
    case View::Machine: return tr("Machine view");
    case View::Panel: return tr("Panel");
    }
    return {};
}

void ReviewWindow::retranslate() {
    const QString trainee = attempt_.trainee.isEmpty() ? tr("(no name)") : attempt_.trainee;
    setWindowTitle(tr("Review: %1 · %2").arg(trainee, QString::fromStdString(exercise_.title.in(spokenLanguage()))));
    bar_->setViewName(viewName());
    if (verdict_) {
        QStringList failed;
        for (const training::CheckResult& check : verdict_->checks) {
            if (!check.passed) {
                failed.append(QString::fromStdString(check.id));
            }
        }
        bar_->setEndText(verdict_->passed ? tr("Handed in: passed")
                                          : tr("Handed in: failed (%1)").arg(failed.join(QStringLiteral(", "))));
    }
}

void ReviewWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange && bar_) {
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

bool ReviewWindow::eventFilter(QObject* watched, QEvent* event) {
    const QEvent::Type type = event->type();
    const bool keyEvent = type == QEvent::KeyPress || type == QEvent::KeyRelease || type == QEvent::ShortcutOverride;
    const bool mouseEvent = type == QEvent::MouseButtonPress || type == QEvent::MouseButtonRelease ||
                            type == QEvent::MouseButtonDblClick || type == QEvent::Wheel;
    // the panel's menu (its language) keeps its keys
    if ((!keyEvent && !mouseEvent) || QApplication::activeWindow() != this || qobject_cast<QMenu*>(watched)) {
        return QMainWindow::eventFilter(watched, event);
    }
    if (keyEvent) {
        if (type == QEvent::KeyPress && bar_->key(*static_cast<QKeyEvent*>(event))) {
            return true;
        }
        return type != QEvent::ShortcutOverride; // the panel is the trainee's: the trainer's keys stop here
    }
    // clicks on the panel's screen and keys do not reach it; the menu (language) and the bar do
    auto* widget = qobject_cast<QWidget*>(watched);
    return widget && panel_->centralWidget() && panel_->centralWidget()->isAncestorOf(widget);
}

QJsonObject ReviewWindow::state() const {
    QJsonObject out{{QStringLiteral("page"), QStringLiteral("review")},
                    {QStringLiteral("review_time"), playback_->now()},
                    {QStringLiteral("review_end"), playback_->end()},
                    {QStringLiteral("review_finished"), playback_->finished()},
                    {QStringLiteral("review_speed"), bar_->speed()},
                    {QStringLiteral("review_playing"), bar_->playing()},
                    {QStringLiteral("review_shown"), shown()},
                    {QStringLiteral("review_next"), bar_->nextText()},
                    {QStringLiteral("running_file"), program_->fileName()},
                    {QStringLiteral("running_line"), program_->runningLine()},
                    {QStringLiteral("running_text"), program_->runningText()},
                    {QStringLiteral("panel"), panel_->state()}};
    if (!playback_->error().isEmpty()) {
        out.insert(QStringLiteral("error"), playback_->error());
    }
    if (verdict_) {
        out.insert(QStringLiteral("passed"), verdict_->passed);
        // the checks as the grader's --verdict writes them
        out.insert(QStringLiteral("checks"), QJsonDocument::fromJson(QByteArray::fromStdString(training::verdictJson(*verdict_)))
                                                 .object()
                                                 .value(QStringLiteral("checks")));
    }
    return out;
}

} // namespace m350::ui
