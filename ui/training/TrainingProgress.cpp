#include "ui/training/TrainingProgress.h"

#include "core/files/AtomicFile.h"
#include "ui/i18n/Language.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace m350::ui {

TrainingProgress::TrainingProgress(QString file) : file_(std::move(file)) {
    QFile in(file_);
    if (!in.open(QIODevice::ReadOnly) || in.size() > 16 * 1024 * 1024) {
        return; // none yet (or not ours): every exercise not tried
    }
    const QJsonObject trainees = QJsonDocument::fromJson(in.readAll()).object();
    for (auto trainee = trainees.begin(); trainee != trainees.end(); ++trainee) {
        const QJsonObject exercises = trainee.value().toObject();
        for (auto exercise = exercises.begin(); exercise != exercises.end(); ++exercise) {
            const QJsonObject e = exercise.value().toObject();
            Entry entry;
            entry.tries = e.value(QStringLiteral("tries")).toInt();
            entry.passed = e.value(QStringLiteral("passed")).toBool();
            if (e.contains(QStringLiteral("best_time"))) {
                entry.bestTime = e.value(QStringLiteral("best_time")).toDouble();
            }
            entries_[trainee.key()][exercise.key()] = entry;
        }
    }
}

const TrainingProgress::Entry* TrainingProgress::find(const QString& trainee, const QString& exercise) const {
    auto t = entries_.find(trainee);
    if (t == entries_.end()) {
        return nullptr;
    }
    auto e = t->second.find(exercise);
    return e == t->second.end() ? nullptr : &e->second;
}

QString TrainingProgress::add(const QString& trainee, const QString& exercise, bool passed, double seconds) {
    Entry& entry = entries_[trainee][exercise];
    ++entry.tries;
    if (passed) {
        entry.passed = true;
        entry.bestTime = entry.bestTime ? std::min(*entry.bestTime, seconds) : seconds;
    }
    QJsonObject trainees;
    for (const auto& [name, exercises] : entries_) {
        QJsonObject done;
        for (const auto& [id, e] : exercises) {
            QJsonObject o{{QStringLiteral("tries"), e.tries}, {QStringLiteral("passed"), e.passed}};
            if (e.bestTime) {
                o.insert(QStringLiteral("best_time"), *e.bestTime);
            }
            done.insert(id, o);
        }
        trainees.insert(name, done);
    }
    const QByteArray text = QJsonDocument(trainees).toJson(QJsonDocument::Indented);
    if (auto why = files::writeFileAtomically(file_.toStdString(), std::string_view(text.constData(), static_cast<std::size_t>(text.size())))) {
        return QString::fromStdString(why->in(Language::messageLanguage()));
    }
    return {};
}

} // namespace m350::ui
