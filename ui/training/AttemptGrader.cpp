#include "ui/training/AttemptGrader.h"

#include "core/config/MachineConfig.h"
#include "core/files/ScratchFolder.h"
#include "core/training/ExerciseFile.h"
#include "core/training/FactsFromController.h"
#include "ui/i18n/Language.h"
#include "ui/panel/MainWindow.h"
#include "ui/training/AttemptFile.h"
#include "ui/training/ExerciseRun.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QFile>
#include <QTemporaryDir>

#include <variant>

namespace m350::ui {

namespace {

MessageLanguage languageOf(const Language* language) {
    return language && language->current() == QLatin1String("en") ? MessageLanguage::English : MessageLanguage::Chinese;
}

QString said(const Message& words, const Language* language) { return QString::fromStdString(words.in(languageOf(language))); }

} // namespace

GradeOutcome gradeAttemptFile(const GradeRequest& request) {
    GradeOutcome outcome;
    auto loaded = training::loadExercise(request.exerciseFolder.toStdString(), config::bundledMachinesDirectory());
    if (auto* error = std::get_if<training::ExerciseError>(&loaded)) {
        outcome.error = QString::fromStdString(error->where()) + QStringLiteral(": ") + said(error->words, request.language);
        return outcome;
    }
    const training::Exercise& exercise = std::get<training::Exercise>(loaded);
    QFile tomlFile(QDir(request.exerciseFolder).filePath(QString::fromLatin1(training::kExerciseFileName)));
    if (!tomlFile.open(QIODevice::ReadOnly)) {
        outcome.error = QStringLiteral("%1: cannot read: %2").arg(tomlFile.fileName(), tomlFile.errorString());
        return outcome;
    }
    const QByteArray exerciseToml = tomlFile.readAll();
    std::optional<Attempt> attempt = readAttempt(request.attemptFile, exerciseToml, request.examKey, &outcome.error);
    if (!attempt) {
        return outcome;
    }
    if (request.requireChain && !attempt->chained) {
        outcome.error = QStringLiteral("%1: the attempt carries no hash chain: an exam takes only attempts the panel "
                                       "recorded in the exam")
                            .arg(request.attemptFile);
        return outcome;
    }
    if (!attempt->exercise.isEmpty() && attempt->exercise != QString::fromStdString(exercise.name)) {
        outcome.error = QStringLiteral("%1:1: the attempt is at exercise \"%2\", not \"%3\"")
                            .arg(request.attemptFile, attempt->exercise, QString::fromStdString(exercise.name));
        return outcome;
    }
    QTemporaryDir scratch;
    files::setScratchFolder(scratch.path().toStdString()); // thrown away after grading: nothing there is synced
    const QString folder = scratch.filePath(QStringLiteral("machine"));
    if (auto why = prepareAttemptMachine(exercise, folder)) {
        outcome.error = said(*why, request.language);
        return outcome;
    }
    auto config = config::loadMachineFolder(folder.toStdString());
    if (auto* error = std::get_if<config::ConfigError>(&config)) {
        outcome.error = QString::fromStdString(error->where()) + QStringLiteral(": ") + said(error->message, request.language);
        return outcome;
    }
    MachineSession session(std::move(std::get<config::MachineConfig>(config)),
                           attemptSessionOptions(exercise, MachineSession::Clock::Manual));
    MainWindow window(session, folder, request.language);
    window.resize(1024, 600);
    window.show();
    settle(session);
    double start = 0.0;
    session.examine([&start](controller::Controller& controller) { start = controller.displayTime(); });
    std::vector<OperatorAction> actions = attempt->actions;
    std::vector<ReplayPlace> places = attempt->places;
    injectFaults(exercise, actions, places);
    const double end = attempt->timeUsed();
    if (actions.empty() || actions.back().t < end) {
        OperatorAction handIn;
        handIn.t = end; // time passes to the hand-in: a fault or a run still going has its say
        actions.push_back(handIn);
        places.push_back({0, 1});
    }
    if (QString error = playReplay(window, session, actions, request.attemptFile, places); !error.isEmpty()) {
        outcome.error = error;
        return outcome;
    }
    training::AttemptFacts facts;
    session.examine([&](controller::Controller& controller) {
        facts = training::factsFromController(controller, exercise, start, folder.toStdString());
    });
    for (const OperatorAction& action : attempt->actions) {
        if (action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown) {
            facts.keys.push_back({action.t, action.name.toStdString()});
        }
    }
    facts.timeUsed = end;
    training::Verdict verdict = training::gradeAttempt(exercise, facts);
    verdict.trainee = attempt->trainee.toStdString();
    verdict.hintsUsed = attempt->hints;
    verdict.timedOut = verdict.timedOut || attempt->timedOut;
    verdict.passed = verdict.passed && !verdict.timedOut;
    outcome.verdict = std::move(verdict);
    return outcome;
}

std::optional<QString> refusedVerdictOutput(const QString& verdict, const QString& attempt, const QString& exerciseFolder) {
    const QFileInfo output(verdict);
    const QString target = output.exists() ? output.canonicalFilePath()
                                           : QFileInfo(output.absolutePath()).canonicalFilePath() + QLatin1Char('/') + output.fileName();
    if (target == QFileInfo(attempt).canonicalFilePath()) {
        return QCoreApplication::translate("m350::ui::AttemptGrader", "--verdict %1 is the attempt it grades: refused, nothing written")
            .arg(verdict);
    }
    if (target.startsWith(QFileInfo(exerciseFolder).canonicalFilePath() + QLatin1Char('/'))) {
        return QCoreApplication::translate("m350::ui::AttemptGrader", "--verdict %1 lies in the exercise folder %2: refused, nothing written")
            .arg(verdict, exerciseFolder);
    }
    return std::nullopt;
}

} // namespace m350::ui
