#include "app/hmi/TrainingCommand.h"

#include "app/hmi/ExamOption.h"

#include "app/hmi/HmiOutputs.h"
#include "app/hmi/Refusal.h"
#include "core/training/Exam.h"
#include "core/training/ExerciseFile.h"
#include "ui/i18n/Language.h"
#include "ui/panel/MainWindow.h"
#include "ui/replay/Replay.h"
#include "ui/training/AttemptFile.h"
#include "ui/training/AttemptRun.h"
#include "ui/training/ExerciseRun.h"
#include "ui/training/TrainingStartPage.h"
#include "ui/training/TrainingWindow.h"

#include <QApplication>
#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cstdio>
#include <variant>

namespace m350::hmi {

namespace {

// Plays the attempt file through the training window: start the exercise, the actions on its
// panel, then the hand-in when the attempt has one.
QString playAttempt(ui::TrainingWindow& window, const HmiOptions& o, const QByteArray& examKey, const ui::Language& language) {
    const QString exerciseName = QFileInfo(QString::fromStdString(o.exercise)).fileName();
    const auto& exercises = window.exercises();
    const auto found = std::find_if(exercises.begin(), exercises.end(),
                                    [&](const training::Exercise& e) { return QString::fromStdString(e.name) == exerciseName; });
    if (found == exercises.end()) {
        return language.say(message("training_not_an_exercise", {o.exercise, window.problems().join(QStringLiteral("; ")).toStdString()}));
    }
    window.startPage()->select(static_cast<int>(found - exercises.begin()));
    QFile toml(QDir(QString::fromStdString(found->folder)).filePath(QString::fromLatin1(training::kExerciseFileName)));
    const QByteArray exerciseToml = toml.open(QIODevice::ReadOnly) ? toml.readAll() : QByteArray();
    QString error;
    std::optional<ui::Attempt> attempt = ui::readAttempt(QString::fromStdString(o.replay), exerciseToml, examKey, &error);
    if (!attempt) {
        return error;
    }
    window.softkey(1);
    ui::AttemptRun* run = window.attempt();
    if (!run) {
        return window.startPage()->text();
    }
    std::vector<ui::OperatorAction> actions = attempt->actions;
    std::vector<ui::ReplayPlace> places = attempt->places;
    ui::injectFaults(run->exercise(), actions, places);
    if (attempt->handedInAt && (actions.empty() || actions.back().t < *attempt->handedInAt)) {
        ui::OperatorAction wait;
        wait.t = *attempt->handedInAt;
        actions.push_back(wait);
        places.push_back({0, 1});
    }
    error = ui::playReplay(run->window(), run->session(), actions, QString::fromStdString(o.replay), places);
    if (!error.isEmpty()) {
        return error;
    }
    for (int hint = 0; hint < attempt->hints; ++hint) {
        run->takeHint();
    }
    if (attempt->handedInAt) {
        window.handIn(attempt->timedOut, attempt->handedInAt);
    }
    return {};
}

} // namespace

int trainingCommand(QApplication& app, const HmiOptions& o, ui::Language& language) {
    ui::TrainingWindow::Options options;
    options.exercisesFolder = QString::fromStdString(o.exercises.empty() ? training::bundledExercisesDirectory() : o.exercises);
    options.trainee = QString::fromStdString(o.trainee);
    options.language = &language;
    QTemporaryDir scratch;
    options.attemptsFolder = !o.attempts.empty() ? QString::fromStdString(o.attempts)
                             : o.headlessRun()   ? scratch.path()
                                                 : QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                                                     QStringLiteral("/training");
    if (!QDir().mkpath(options.attemptsFolder)) {
        return refuse(language.say(message("training_attempts_folder", {options.attemptsFolder.toStdString()})));
    }
    if (!o.exam.empty()) {
        training::Exam exam;
        if (auto refused = readExamOption(o.exam, language, &exam)) {
            return refuse(QString::fromStdString(*refused));
        }
        options.exam = exam;
    }
    options.clock = o.headlessRun() ? ui::MachineSession::Clock::Manual : ui::MachineSession::Clock::RealTime;
    ui::TrainingWindow window(options);
    window.resize(o.width, o.height);
    window.show();
    if (!o.headlessRun()) {
        return app.exec();
    }
    if (!o.replay.empty()) {
        if (o.exercise.empty()) {
            return refuse(language.say(message("training_replay_needs_exercise")));
        }
        if (QString error = playAttempt(window, o, options.exam ? QByteArray::fromStdString(options.exam->key) : QByteArray(), language);
            !error.isEmpty()) {
            return refuse(error);
        }
    }
    if (window.attempt()) {
        ui::settle(window.attempt()->session());
    }
    QCoreApplication::processEvents();
    if (!o.screenshot.empty()) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        if (!window.grab().save(&buffer, screenshotFormat(o.screenshot)->constData())) {
            return refuse(language.say(message("hmi_image_failed", {o.screenshot})));
        }
        if (auto error = writeOutput(o.screenshot, png)) {
            return refuse(QStringLiteral("--screenshot: %1").arg(*error));
        }
    }
    if (!o.state.empty()) {
        if (auto error = writeOutput(o.state, QJsonDocument(window.state()).toJson(QJsonDocument::Indented))) {
            return refuse(QStringLiteral("--state: %1").arg(*error));
        }
    }
    return 0;
}

} // namespace m350::hmi
