#pragma once

#include "ui/actions/OperatorAction.h"
#include "ui/replay/Replay.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <utility>
#include <vector>

namespace m350::ui {

// A trainee's attempt at an exercise: a replay file (the trainee's own actions, as --replay plays
// them) with a first line naming the exercise and the trainee and a last line for the hand-in:
//   {"attempt":{"exercise":"rack-commission","trainee":"王伟"}}
//   {"t":0.5,"key":"START"} ...
//   {"t":312.4,"handin":{"hints":1,"timeout":false}}
// The exercise's injected faults are not in it: the grader and the panel inject them alike.
// Chained (every attempt the panel records): each line carries "h", the hex SHA-256 HMAC, keyed by
// the exam's key (empty outside an exam), of the previous line's "h" and this line without it; the
// first line's previous is the HMAC of exercise.toml. An edited, removed or inserted line breaks the
// chain from there on; the grader then refuses the attempt at that line.
struct Attempt {
    QString exercise;
    QString trainee;
    std::vector<OperatorAction> actions;
    std::vector<ReplayPlace> places;
    std::optional<double> handedInAt; // nullopt: the file ends without a hand-in (the last action's time counts)
    int hints = 0;
    bool timedOut = false;
    bool chained = false; // every line carried a hash, and the chain held
    double timeUsed() const;
};

// Reads an attempt. `exerciseToml`: the bytes of the exercise's exercise.toml (the chain's seed);
// `key`: the exam's key. A line whose hash does not follow the chain, or a file in which some lines
// are hashed and some are not, is refused at its line. Errors name file:line:col.
std::optional<Attempt> readAttempt(const QString& path, const QByteArray& exerciseToml, const QByteArray& key,
                                   QString* error);

// The exercise and the trainee the attempt's first line names (empty when it names none), without
// reading the rest: how a class report and a review find them.
std::pair<QString, QString> attemptHeader(const QString& path);

// Writes an attempt as it goes (the panel's training mode): each line hashed into the chain and
// flushed at once, so that a crash loses at most the line being written.
class AttemptWriter {
public:
    AttemptWriter(const QByteArray& exerciseToml, const QByteArray& key);
    // The header line; then each action, then the hand-in.
    QByteArray header(const QString& exercise, const QString& trainee);
    QByteArray action(const OperatorAction& action);
    QByteArray handIn(double t, int hints, bool timedOut);

private:
    QByteArray line(QJsonObject object);
    QByteArray key_;
    QByteArray previous_;
};

// The chain's link: HMAC-SHA256(key, previous + compact JSON of the line without "h"), hex.
QByteArray attemptLinkHash(const QByteArray& key, const QByteArray& previous, const QJsonObject& lineWithoutHash);
QByteArray attemptChainSeed(const QByteArray& key, const QByteArray& exerciseToml);

} // namespace m350::ui
