#include "ui/training/TrainingWindow.h"

#include "core/config/MachineConfig.h"
#include "core/training/ExerciseFile.h"
#include "ui/actions/OperatorAction.h"
#include "ui/i18n/Language.h"
#include "ui/pages/PageId.h"
#include "ui/pages/ParamPage.h"
#include "ui/pages/ProgramPage.h"
#include "ui/panel/MainWindow.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/training/AttemptRun.h"
#include "ui/training/TrainingStartPage.h"
#include "ui/training/VerdictPage.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace m350::ui {

TrainingWindow::TrainingWindow(Options options, QWidget* parent)
    : QMainWindow(parent), options_(std::move(options)),
      progress_(QDir(options_.attemptsFolder).filePath(QStringLiteral("progress.json"))) {
    setObjectName("trainingWindow");
    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    stack_ = new QStackedWidget(central);
    start_ = new TrainingStartPage(stack_);
    attemptHolder_ = new QWidget(stack_);
    attemptLayout_ = new QVBoxLayout(attemptHolder_);
    attemptLayout_->setContentsMargins(0, 0, 0, 0);
    verdict_ = new VerdictPage(stack_);
    stack_->addWidget(start_);
    stack_->addWidget(attemptHolder_);
    stack_->addWidget(verdict_);
    softkeys_ = new SoftkeyBar(central);
    column->addWidget(stack_, 1);
    column->addWidget(softkeys_);
    setCentralWidget(central);
    connect(softkeys_, &SoftkeyBar::pressed, this, &TrainingWindow::softkey);
    qApp->installEventFilter(this);
    resize(1024, 600);
    loadExercises();
    refreshStart();
    if (!exercises_.empty()) {
        start_->showText(QString::fromStdString(exercises_.front().task.in(language())));
    }
    if (!problems_.isEmpty()) {
        start_->showText(problems_.join(QLatin1Char('\n')));
    }
    showPage(start_);
}

TrainingWindow::~TrainingWindow() {
    qApp->removeEventFilter(this);
    attempt_.reset();
}

MessageLanguage TrainingWindow::language() const {
    return spokenBy(options_.language);
}

void TrainingWindow::loadExercises() {
    training::ExerciseListing listing =
        training::loadExercises(options_.exercisesFolder.toStdString(), config::bundledMachinesDirectory());
    for (const training::ExerciseError& error : listing.errors) {
        problems_.append(QString::fromStdString(error.where() + ": " + error.words.in(language())));
    }
    if (!options_.exam) {
        exercises_ = std::move(listing.exercises);
        return;
    }
    for (const std::string& name : options_.exam->exercises) {
        auto found = std::find_if(listing.exercises.begin(), listing.exercises.end(),
                                  [&](const training::Exercise& e) { return e.name == name; });
        if (found == listing.exercises.end()) {
            problems_.append(tr("The exam names exercise %1, which is not in %2").arg(QString::fromStdString(name), options_.exercisesFolder));
            continue;
        }
        training::Exercise exercise = *found;
        if (options_.exam->timeLimit) {
            exercise.timeLimit = *options_.exam->timeLimit;
        }
        exercises_.push_back(std::move(exercise));
    }
}

void TrainingWindow::refreshStart() { start_->show(exercises_, progress_, options_.trainee, language()); }

void TrainingWindow::showPage(QWidget* page) {
    stack_->setCurrentWidget(page);
    softkeys_->setVisible(page != attemptHolder_);
    refreshSoftkeys();
}

QString TrainingWindow::pageId() const {
    QWidget* page = stack_->currentWidget();
    return page == start_ ? QStringLiteral("training") : page == verdict_ ? QStringLiteral("verdict") : QStringLiteral("attempt");
}

void TrainingWindow::refreshSoftkeys() {
    const bool running = attempt_ && !attempt_->handedIn();
    auto key = [](const QString& text, bool enabled = true) {
        Page::Softkey k;
        k.text = text;
        k.enabled = enabled;
        return k;
    };
    if (stack_->currentWidget() == verdict_) {
        softkeys_->show({key(tr("Training")), key({}), key({}), key({}),
                         key(tr("Open"), verdict_->target().kind != training::CheckTarget::Kind::None), key(tr("Back"))});
        return;
    }
    const bool hints = !options_.exam && running;
    softkeys_->show({key(running ? tr("Panel") : tr("Start"), !exercises_.empty()), key(tr("Task"), !exercises_.empty()),
                     key(options_.exam ? tr("No hints (exam)") : tr("Hint"), hints), key(tr("Hand in"), running), key({}),
                     key({})});
}

QString TrainingWindow::attemptPath(const training::Exercise& exercise) const {
    const QString trainee = options_.trainee.isEmpty() ? QStringLiteral("trainee") : options_.trainee;
    QDir folder(options_.attemptsFolder);
    folder.mkpath(trainee);
    return folder.filePath(trainee + QLatin1Char('/') + QString::fromStdString(exercise.name) + QLatin1Char('-') +
                           QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")) +
                           QStringLiteral(".jsonl"));
}

void TrainingWindow::startSelected() {
    const int row = start_->selected();
    if (row < 0 || row >= static_cast<int>(exercises_.size())) {
        return;
    }
    if (attempt_ && !attempt_->handedIn()) {
        showPage(attemptHolder_); // F1 during an attempt: back to its panel
        return;
    }
    attempt_.reset();
    const training::Exercise& exercise = exercises_[static_cast<std::size_t>(row)];
    QFile toml(QDir(QString::fromStdString(exercise.folder)).filePath(QString::fromLatin1(training::kExerciseFileName)));
    AttemptRun::Setup setup;
    setup.exercise = exercise;
    setup.exerciseToml = toml.open(QIODevice::ReadOnly) ? toml.readAll() : QByteArray();
    setup.trainee = options_.trainee;
    setup.attemptFile = attemptPath(exercise);
    setup.examKey = options_.exam ? QByteArray::fromStdString(options_.exam->key) : QByteArray();
    setup.hintsAllowed = !options_.exam;
    setup.clock = options_.clock;
    setup.language = options_.language;
    QString error;
    attempt_ = AttemptRun::start(std::move(setup), &error);
    if (!attempt_) {
        start_->showText(error);
        return;
    }
    attemptExercise_ = row;
    attemptLayout_->addWidget(&attempt_->window());
    attempt_->window().show();
    connect(attempt_.get(), &AttemptRun::timeUp, this, [this] { handIn(true); });
    showPage(attemptHolder_);
}

void TrainingWindow::handIn(bool timedOut, std::optional<double> at) {
    if (!attempt_ || attempt_->handedIn()) {
        return;
    }
    const training::Verdict& verdict = attempt_->handIn(timedOut, at);
    const training::Exercise& exercise = exercises_[static_cast<std::size_t>(attemptExercise_)];
    if (QString why = progress_.add(options_.trainee, QString::fromStdString(exercise.name), verdict.passed, verdict.timeUsed);
        !why.isEmpty()) {
        start_->showText(why);
    }
    refreshStart();
    verdict_->show(verdict, QString::fromStdString(exercise.title.in(language())), language());
    showPage(verdict_);
}

void TrainingWindow::openTarget() {
    const training::CheckTarget target = verdict_->target();
    if (!attempt_ || target.kind == training::CheckTarget::Kind::None) {
        return;
    }
    MainWindow& panel = attempt_->window();
    switch (target.kind) {
    case training::CheckTarget::Kind::Parameter:
        panel.showPage(PageId::param);
        if (auto* page = dynamic_cast<ParamPage*>(panel.page(PageId::param))) {
            page->select(target.number);
        }
        break;
    case training::CheckTarget::Kind::Line:
        panel.showPage(PageId::program);
        if (auto* page = dynamic_cast<ProgramPage*>(panel.page(PageId::program))) {
            page->editAt(panel.context().machineFolder() + QLatin1Char('/') + QString::fromStdString(target.file), target.line);
        }
        break;
    case training::CheckTarget::Kind::Output: panel.showPage(PageId::io); break;
    case training::CheckTarget::Kind::Tool: panel.showPage(PageId::tools); break;
    case training::CheckTarget::Kind::None: break;
    }
    showPage(attemptHolder_);
}

void TrainingWindow::softkey(int number) {
    if (stack_->currentWidget() == verdict_) {
        if (number == 5) {
            openTarget();
        } else if (number == 1 || number == 6) {
            showPage(start_);
        }
        return;
    }
    const int row = start_->selected();
    const bool valid = row >= 0 && row < static_cast<int>(exercises_.size());
    switch (number) {
    case 1: startSelected(); break;
    case 2:
        if (valid) {
            const training::Exercise& e = exercises_[static_cast<std::size_t>(attempt_ && !attempt_->handedIn() ? attemptExercise_ : row)];
            start_->showText(QString::fromStdString(e.task.in(language())));
        }
        break;
    case 3:
        if (attempt_ && !attempt_->handedIn() && !options_.exam) {
            const QString hint = attempt_->takeHint();
            start_->showText(hint.isEmpty() ? tr("No more hints for this exercise.")
                                            : tr("Hint %1: %2").arg(attempt_->hintsTaken()).arg(hint));
        }
        break;
    case 4: handIn(false); break;
    default: break;
    }
    refreshSoftkeys();
}

void TrainingWindow::key(const QString& name) {
    if (name == QLatin1String("TRAINING")) {
        if (stack_->currentWidget() == attemptHolder_) {
            showPage(attempt_ && attempt_->handedIn() ? static_cast<QWidget*>(verdict_) : start_);
        } else if (attempt_) {
            showPage(attemptHolder_);
        }
        return;
    }
    const int by = name == QLatin1String("UP") ? -1 : name == QLatin1String("DOWN") ? 1 : 0;
    if (by == 0) {
        return;
    }
    if (stack_->currentWidget() == verdict_) {
        verdict_->move(by);
        refreshSoftkeys();
    } else if (stack_->currentWidget() == start_) {
        start_->move(by);
        if (!(attempt_ && !attempt_->handedIn())) {
            const int row = start_->selected();
            if (row >= 0 && row < static_cast<int>(exercises_.size())) {
                start_->showText(QString::fromStdString(exercises_[static_cast<std::size_t>(row)].task.in(language())));
            }
        }
    }
}

bool TrainingWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress || QApplication::activeWindow() != this) {
        return QMainWindow::eventFilter(watched, event);
    }
    const auto* press = static_cast<QKeyEvent*>(event);
    if (press->key() == Qt::Key_F7) {
        key(QStringLiteral("TRAINING"));
        return true;
    }
    if (stack_->currentWidget() == attemptHolder_) {
        return false; // the panel's own keys
    }
    if (press->key() >= Qt::Key_F1 && press->key() <= Qt::Key_F6) {
        softkey(press->key() - Qt::Key_F1 + 1);
        return true;
    }
    if (press->key() == Qt::Key_Up || press->key() == Qt::Key_Down) {
        key(press->key() == Qt::Key_Up ? QStringLiteral("UP") : QStringLiteral("DOWN"));
        return true;
    }
    return false;
}

QJsonObject TrainingWindow::state() const {
    QJsonObject out{{QStringLiteral("page"), pageId()},
                    {QStringLiteral("selected"), start_->selected()},
                    {QStringLiteral("text"), start_->text()},
                    {QStringLiteral("exercises"), static_cast<int>(exercises_.size())}};
    if (attempt_) {
        out.insert(QStringLiteral("attempt_file"), attempt_->attemptFile());
        out.insert(QStringLiteral("time_left"), attempt_->timeLeft());
        out.insert(QStringLiteral("hints"), attempt_->hintsTaken());
        out.insert(QStringLiteral("panel"), attempt_->window().state());
    }
    if (attempt_ && attempt_->verdict()) {
        out.insert(QStringLiteral("verdict"), verdict_->summary());
        out.insert(QStringLiteral("passed"), attempt_->verdict()->passed);
        // the checks as the grader's --verdict writes them
        out.insert(QStringLiteral("checks"), QJsonDocument::fromJson(QByteArray::fromStdString(training::verdictJson(*attempt_->verdict())))
                                                 .object()
                                                 .value(QStringLiteral("checks")));
    }
    return out;
}

} // namespace m350::ui
