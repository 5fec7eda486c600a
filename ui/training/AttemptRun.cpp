#include "ui/training/AttemptRun.h"

#include "core/config/MachineConfig.h"
#include "core/training/FactsFromController.h"
#include "ui/actions/ActionDispatcher.h"
#include "ui/actions/ActionRecorder.h"
#include "ui/i18n/Language.h"
#include "ui/panel/MainWindow.h"
#include "ui/training/AttemptFile.h"
#include "ui/training/ExerciseRun.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <variant>

namespace m350::ui {

namespace {

} // namespace

AttemptRun::AttemptRun(Setup setup) : setup_(std::move(setup)), injected_(setup_.exercise.faults.size(), false) {}

AttemptRun::~AttemptRun() {
    if (window_ && window_->recording()) {
        window_->stopRecording();
    }
    window_.reset();
    session_.reset();
}

std::unique_ptr<AttemptRun> AttemptRun::start(Setup setup, QString* error) {
    std::unique_ptr<AttemptRun> run(new AttemptRun(std::move(setup)));
    const MessageLanguage language = spokenBy(run->setup_.language);
    if (!run->folder_.isValid()) {
        *error = AttemptRun::tr("no folder for the attempt's machine: %1").arg(run->folder_.errorString());
        return nullptr;
    }
    const QString machine = run->folder_.filePath(QStringLiteral("machine"));
    if (auto why = prepareAttemptMachine(run->setup_.exercise, machine)) {
        *error = QString::fromStdString(why->in(language));
        return nullptr;
    }
    auto loaded = config::loadMachineFolder(machine.toStdString());
    if (auto* failed = std::get_if<config::ConfigError>(&loaded)) {
        *error = QString::fromStdString(failed->where() + ": " + failed->message.in(language));
        return nullptr;
    }
    run->session_ = std::make_unique<MachineSession>(std::move(std::get<config::MachineConfig>(loaded)),
                                                     attemptSessionOptions(run->setup_.exercise, run->setup_.clock));
    run->window_ = std::make_unique<MainWindow>(*run->session_, machine, run->setup_.language);
    AttemptRun* self = run.get();
    run->session_->sync();
    run->session_->examine([self](controller::Controller& controller) { self->startDisplay_ = training::attemptClock(controller); });
    run->now_ = run->session_->latest() ? run->session_->latest()->sessionTime : 0.0;
    auto writer = std::make_shared<AttemptWriter>(run->setup_.exerciseToml, run->setup_.examKey);
    ActionRecorder& recorder = run->window_->recorder();
    // a fault on an input is the exercise's doing (or a trainer's), never the trainee's: not recorded
    recorder.setFormat([writer](const OperatorAction& action) {
        return action.kind == OperatorAction::Kind::Force ? QByteArray() : writer->action(action);
    });
    if (!run->window_->startRecording(run->setup_.attemptFile, error)) {
        return nullptr;
    }
    recorder.writeExtra(writer->header(QString::fromStdString(run->setup_.exercise.name), run->setup_.trainee));
    QObject::connect(&recorder, &ActionRecorder::failed, self, [self](const QString& why) { self->recordingError_ = why; });
    self->writer_ = writer; // the hand-in line is its last
    QObject::connect(&run->window_->dispatcher(), &ActionDispatcher::dispatched, self, [self](const OperatorAction& action) {
        if (!self->firstStart_ && (action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown) &&
            action.name == QLatin1String("START")) {
            self->firstStart_ = self->now_;
        }
    });
    QObject::connect(run->session_.get(), &MachineSession::snapshotReady, self, &AttemptRun::onSnapshot);
    run->showNote(run->setup_.exercise.timeLimit);
    run->injectDueFaults(run->now_);
    return run;
}

// The session is the attempt's own: its clock since power-on is the attempt's (the recorded
// actions' `t`, as the headless grader plays them).
double AttemptRun::timeUsed() const { return now_; }

void AttemptRun::onSnapshot(const SnapshotPtr& snapshot) {
    if (verdict_) {
        return;
    }
    now_ = snapshot->sessionTime;
    injectDueFaults(now_);
    const double left = timeLeft();
    showNote(left);
    if (left <= 0.0 && !timeUpSent_) {
        timeUpSent_ = true;
        emit timeUp();
    }
}

void AttemptRun::injectDueFaults(double now) {
    if (setup_.clock != MachineSession::Clock::RealTime) {
        return; // a replayed attempt has them among its actions at their exact times (injectFaults)
    }
    for (std::size_t i = 0; i < setup_.exercise.faults.size(); ++i) {
        const training::InjectedFault& fault = setup_.exercise.faults[i];
        if (injected_[i]) {
            continue;
        }
        double at = fault.at;
        if (fault.after == training::InjectedFault::After::FirstStart) {
            if (!firstStart_) {
                continue;
            }
            at += *firstStart_;
        }
        if (now + 1e-9 >= at) {
            injected_[i] = true;
            window_->dispatcher().dispatch(faultAction(fault, at));
        }
    }
}

void AttemptRun::showNote(double left) {
    const int second = static_cast<int>(std::ceil(std::max(0.0, left)));
    if (second == shownSecond_) {
        return;
    }
    shownSecond_ = second;
    const QString task = QString::fromStdString(setup_.exercise.title.in(spokenBy(setup_.language)));
    window_->setStandingNote(AttemptRun::tr("Training: %1 · time left %2:%3 · F7: task, hint, hand in")
                                 .arg(task)
                                 .arg(second / 60)
                                 .arg(second % 60, 2, 10, QLatin1Char('0')));
    emit ticked(left);
}

QString AttemptRun::takeHint() {
    if (!setup_.hintsAllowed || hints_ >= static_cast<int>(setup_.exercise.hints.size())) {
        return {};
    }
    return QString::fromStdString(setup_.exercise.hints[static_cast<std::size_t>(hints_++)].in(spokenBy(setup_.language)));
}

const training::Verdict& AttemptRun::handIn(bool timedOut, std::optional<double> at) {
    if (verdict_) {
        return *verdict_;
    }
    session_->sync();
    const double sessionNow = session_->latest() ? session_->latest()->sessionTime : now_;
    // a played attempt's hand-in time; never before the last recorded action (whose time is the
    // session's, summed frame by frame)
    now_ = at ? std::max(*at, sessionNow) : sessionNow;
    const double used = timeUsed();
    window_->recorder().writeExtra(writer_->handIn(now_, hints_, timedOut));
    if (QString why = window_->stopRecording(); !why.isEmpty()) {
        recordingError_ = why;
    }
    training::AttemptFacts facts;
    const std::string folder = folder_.filePath(QStringLiteral("machine")).toStdString();
    session_->examine([&](controller::Controller& controller) {
        facts = training::factsFromController(controller, setup_.exercise, startDisplay_, folder);
    });
    QString error;
    if (std::optional<Attempt> recorded = readAttempt(setup_.attemptFile, setup_.exerciseToml, setup_.examKey, &error)) {
        for (const OperatorAction& action : recorded->actions) {
            if (action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown) {
                facts.keys.push_back({action.t, action.name.toStdString()});
            }
        }
    } else if (recordingError_.isEmpty()) {
        recordingError_ = error;
    }
    facts.timeUsed = used;
    training::Verdict verdict = training::gradeAttempt(setup_.exercise, facts);
    verdict.trainee = setup_.trainee.toStdString();
    verdict.hintsUsed = hints_;
    verdict.timedOut = verdict.timedOut || timedOut;
    verdict.passed = verdict.passed && !verdict.timedOut;
    verdict_ = std::move(verdict);
    window_->setStandingNote({});
    return *verdict_;
}

} // namespace m350::ui
