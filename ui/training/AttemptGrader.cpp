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

QString said(const Message& words, const Language* language) { return QString::fromStdString(words.in(spokenBy(language))); }

} // namespace

std::optional<AttemptAtExercise> readAttemptAtExercise(const GradeRequest& request, QString* error) {
    auto loaded = training::loadExercise(request.exerciseFolder.toStdString(), config::bundledMachinesDirectory());
    if (auto* refused = std::get_if<training::ExerciseError>(&loaded)) {
        *error = QString::fromStdString(refused->where()) + QStringLiteral(": ") + said(refused->words, request.language);
        return std::nullopt;
    }
    const training::Exercise& exercise = std::get<training::Exercise>(loaded);
    QFile tomlFile(QDir(request.exerciseFolder).filePath(QString::fromLatin1(training::kExerciseFileName)));
    if (!tomlFile.open(QIODevice::ReadOnly)) {
        *error = QCoreApplication::translate("m350::ui::AttemptGrader", "%1: cannot read: %2").arg(tomlFile.fileName(), tomlFile.errorString());
        return std::nullopt;
    }
    const QByteArray exerciseToml = tomlFile.readAll();
    std::optional<Attempt> attempt = readAttempt(request.attemptFile, exerciseToml, request.examKey, error);
    if (!attempt) {
        return std::nullopt;
    }
    if (request.requireChain && !attempt->chained) {
        *error = QCoreApplication::translate("m350::ui::AttemptGrader", "%1: the attempt carries no hash chain: an exam takes only attempts the panel "
                                "recorded in the exam")
                     .arg(request.attemptFile);
        return std::nullopt;
    }
    if (!attempt->exercise.isEmpty() && attempt->exercise != QString::fromStdString(exercise.name)) {
        *error = QCoreApplication::translate("m350::ui::AttemptGrader", "%1:1: the attempt is at exercise \"%2\", not \"%3\"")
                     .arg(request.attemptFile, attempt->exercise, QString::fromStdString(exercise.name));
        return std::nullopt;
    }
    return AttemptAtExercise{exercise, std::move(*attempt)};
}

GradeOutcome gradeAttemptFile(const GradeRequest& request) {
    GradeOutcome outcome;
    std::optional<AttemptAtExercise> read = readAttemptAtExercise(request, &outcome.error);
    if (!read) {
        return outcome;
    }
    const training::Exercise& exercise = read->exercise;
    const Attempt* attempt = &read->attempt;
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
    session.examine([&start](controller::Controller& controller) { start = training::attemptClock(controller); });
    std::vector<ReplayPlace> places;
    const std::vector<OperatorAction> actions = gradedActions(exercise, *attempt, &places);
    if (QString error = playReplay(window, session, actions, request.attemptFile, places); !error.isEmpty()) {
        outcome.error = error;
        return outcome;
    }
    outcome.verdict = gradePlayedAttempt(session, exercise, *attempt, start, folder);
    return outcome;
}

training::Verdict gradePlayedAttempt(MachineSession& session, const training::Exercise& exercise, const Attempt& attempt,
                                     double startDisplay, const QString& folder) {
    training::AttemptFacts facts;
    session.examine([&](controller::Controller& controller) {
        facts = training::factsFromController(controller, exercise, startDisplay, folder.toStdString());
    });
    for (const OperatorAction& action : attempt.actions) {
        if (action.kind == OperatorAction::Kind::Key || action.kind == OperatorAction::Kind::KeyDown) {
            facts.keys.push_back({action.t, action.name.toStdString()});
        }
    }
    facts.timeUsed = attempt.timeUsed();
    training::Verdict verdict = training::gradeAttempt(exercise, facts);
    verdict.trainee = attempt.trainee.toStdString();
    verdict.hintsUsed = attempt.hints;
    verdict.timedOut = verdict.timedOut || attempt.timedOut;
    verdict.passed = verdict.passed && !verdict.timedOut;
    return verdict;
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
