#include "ui/training/AttemptFile.h"

#include <QFile>
#include <QJsonDocument>
#include <QMessageAuthenticationCode>

#include <QCoreApplication>

namespace m350::ui {

double Attempt::timeUsed() const {
    if (handedInAt) {
        return *handedInAt;
    }
    return actions.empty() ? 0.0 : actions.back().t;
}

QByteArray attemptChainSeed(const QByteArray& key, const QByteArray& exerciseToml) {
    return QMessageAuthenticationCode::hash(exerciseToml, key, QCryptographicHash::Sha256).toHex();
}

QByteArray attemptLinkHash(const QByteArray& key, const QByteArray& previous, const QJsonObject& lineWithoutHash) {
    return QMessageAuthenticationCode::hash(previous + QJsonDocument(lineWithoutHash).toJson(QJsonDocument::Compact), key,
                                            QCryptographicHash::Sha256)
        .toHex();
}

std::optional<Attempt> readAttempt(const QString& path, const QByteArray& exerciseToml, const QByteArray& key,
                                   QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QCoreApplication::translate("m350::ui::AttemptFile", "%1: cannot read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    Attempt attempt;
    int lineNumber = 0;
    int hashed = 0;
    int lines = 0;
    double previousTime = 0.0;
    QByteArray previousHash = attemptChainSeed(key, exerciseToml);
    ReplayLineProblem problem;
    auto failAt = [&](int column, const QString& why) {
        *error = QStringLiteral("%1:%2:%3: %4").arg(path).arg(lineNumber).arg(column).arg(why);
        return std::nullopt;
    };
    while (!file.atEnd()) {
        ++lineNumber;
        const QByteArray raw = file.readLine();
        std::optional<QJsonObject> object = readReplayObject(raw, &problem);
        if (!object) {
            if (!problem.why.isEmpty()) {
                return failAt(problem.column, problem.why);
            }
            continue;
        }
        if (attempt.handedInAt) {
            return failAt(1, QCoreApplication::translate("m350::ui::AttemptFile", "a line after the hand-in: the attempt ended on the line before"));
        }
        ++lines;
        if (object->contains(QLatin1String("h"))) {
            const QByteArray hash = object->take(QLatin1String("h")).toString().toLatin1();
            if (hashed != lines - 1 || hash != attemptLinkHash(key, previousHash, *object)) {
                return failAt(static_cast<int>(raw.indexOf("\"h\"")) + 1,
                              QCoreApplication::translate("m350::ui::AttemptFile", "the line's hash does not follow the chain: the attempt was changed "
                                             "after it was recorded (or belongs to another exercise or exam)"));
            }
            previousHash = hash;
            ++hashed;
        } else if (hashed > 0) {
            return failAt(1, QCoreApplication::translate("m350::ui::AttemptFile", "the line has no hash while the lines before it have: the attempt was "
                                            "changed after it was recorded"));
        }
        if (object->contains(QLatin1String("attempt"))) {
            if (lines != 1) {
                return failAt(static_cast<int>(raw.indexOf("\"attempt\"")) + 1,
                              QCoreApplication::translate("m350::ui::AttemptFile", "\"attempt\" names the exercise and the trainee on the first line only"));
            }
            const QJsonObject header = object->value(QLatin1String("attempt")).toObject();
            attempt.exercise = header.value(QLatin1String("exercise")).toString();
            attempt.trainee = header.value(QLatin1String("trainee")).toString();
            continue;
        }
        if (object->contains(QLatin1String("handin"))) {
            const QJsonObject handIn = object->value(QLatin1String("handin")).toObject();
            const double t = object->value(QLatin1String("t")).toDouble(-1.0);
            if (!(t >= previousTime) || !(t <= kMostReplaySeconds)) {
                return failAt(static_cast<int>(raw.indexOf("\"t\"")) + 1,
                              QCoreApplication::translate("m350::ui::AttemptFile", "the hand-in's t must be a time not before the last action's (%1)").arg(previousTime));
            }
            attempt.handedInAt = t;
            attempt.hints = handIn.value(QLatin1String("hints")).toInt();
            attempt.timedOut = handIn.value(QLatin1String("timeout")).toBool();
            continue;
        }
        int column = 1;
        auto action = readReplayAction(*object, raw, previousTime, &problem, &column);
        if (!action) {
            return failAt(problem.column, problem.why);
        }
        previousTime = action->t;
        attempt.actions.push_back(*action);
        attempt.places.push_back({lineNumber, column});
    }
    attempt.chained = hashed > 0 && hashed == lines;
    return attempt;
}

std::pair<QString, QString> attemptHeader(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    for (int i = 0; i < 5 && !file.atEnd(); ++i) { // past a comment or two, to the first object
        ReplayLineProblem problem;
        if (const std::optional<QJsonObject> object = readReplayObject(file.readLine(), &problem)) {
            const QJsonObject header = object->value(QStringLiteral("attempt")).toObject();
            return {header.value(QStringLiteral("exercise")).toString(), header.value(QStringLiteral("trainee")).toString()};
        }
    }
    return {};
}

AttemptWriter::AttemptWriter(const QByteArray& exerciseToml, const QByteArray& key)
    : key_(key), previous_(attemptChainSeed(key, exerciseToml)) {}

QByteArray AttemptWriter::line(QJsonObject object) {
    previous_ = attemptLinkHash(key_, previous_, object);
    object.insert(QStringLiteral("h"), QString::fromLatin1(previous_));
    return QJsonDocument(object).toJson(QJsonDocument::Compact) + '\n';
}

QByteArray AttemptWriter::header(const QString& exercise, const QString& trainee) {
    return line(QJsonObject{{QStringLiteral("attempt"),
                             QJsonObject{{QStringLiteral("exercise"), exercise}, {QStringLiteral("trainee"), trainee}}}});
}

QByteArray AttemptWriter::action(const OperatorAction& action) { return line(action.toJson()); }

QByteArray AttemptWriter::handIn(double t, int hints, bool timedOut) {
    return line(QJsonObject{{QStringLiteral("t"), t},
                            {QStringLiteral("handin"),
                             QJsonObject{{QStringLiteral("hints"), hints}, {QStringLiteral("timeout"), timedOut}}}});
}

} // namespace m350::ui
