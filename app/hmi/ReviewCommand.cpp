#include "app/hmi/ReviewCommand.h"

#include "app/hmi/ExamOption.h"
#include "core/training/ExerciseFile.h"
#include "ui/training/AttemptFile.h"

#include <QDir>

#include "app/hmi/HmiOutputs.h"
#include "app/hmi/Refusal.h"
#include "core/training/Exam.h"
#include "ui/i18n/Language.h"
#include "ui/replay/Replay.h"
#include "ui/training/ReviewBar.h"
#include "ui/training/ReviewPlayback.h"
#include "ui/training/ReviewWindow.h"

#include <QApplication>
#include <QBuffer>
#include <QJsonDocument>

#include <cstdio>
#include <variant>

namespace m350::hmi {

int reviewCommand(QApplication& app, const HmiOptions& o, ui::Language& language) {
    ui::ReviewWindow::Request request;
    request.exerciseFolder = QString::fromStdString(o.exercise);
    if (request.exerciseFolder.isEmpty()) {
        const QString named = ui::attemptHeader(QString::fromStdString(o.review)).first;
        if (named.isEmpty() || named.contains(QLatin1Char('/')) || named.contains(QStringLiteral(".."))) {
            return refuse(language.say(message("review_no_exercise", {o.review})));
        }
        request.exerciseFolder = QDir(QString::fromStdString(o.exercises.empty() ? training::bundledExercisesDirectory() : o.exercises))
                                     .filePath(named);
    }
    request.attemptFile = QString::fromStdString(o.review);
    request.language = &language;
    if (!o.exam.empty()) {
        training::Exam exam;
        if (auto refused = readExamOption(o.exam, language, &exam)) {
            return refuse(QString::fromStdString(*refused));
        }
        request.examKey = QByteArray::fromStdString(exam.key);
    }
    if (auto refused = refusedOutput(o, request.exerciseFolder)) {
        return refuse(*refused);
    }
    QString error;
    std::unique_ptr<ui::ReviewWindow> window = ui::ReviewWindow::open(request, &error);
    if (!window) {
        return refuse(error);
    }
    window->resize(o.width, o.height);
    window->show();
    if (!o.headlessRun()) {
        return app.exec();
    }
    ui::ReviewPlayback& playback = window->playback();
    const double until = o.reviewUntil.value_or(playback.end());
    playback.play(until - playback.now());
    window->follow();
    window->bar()->retranslate();
    ui::settle(window->session());
    QCoreApplication::processEvents();
    if (!playback.error().isEmpty()) {
        return refuse(playback.error());
    }
    if (!o.screenshot.empty()) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        if (!window->grab().save(&buffer, screenshotFormat(o.screenshot)->constData())) {
            return refuse(language.say(message("hmi_image_failed", {o.screenshot})));
        }
        if (auto failed = writeOutput(o.screenshot, png)) {
            return refuse(QStringLiteral("--screenshot: %1").arg(*failed));
        }
    }
    if (!o.state.empty()) {
        if (auto failed = writeOutput(o.state, QJsonDocument(window->state()).toJson(QJsonDocument::Indented))) {
            return refuse(QStringLiteral("--state: %1").arg(*failed));
        }
    }
    return 0;
}

} // namespace m350::hmi
