#pragma once

#include "ui/actions/OperatorAction.h"

#include <QFile>
#include <QObject>

#include <functional>

namespace m350::ui {

// Writes what the operator does to a replay file (JSON Lines, one action a line, `t` = the
// machine's virtual time when it happened), so a session can be played back with --replay.
class ActionRecorder : public QObject {
    Q_OBJECT
public:
    using Clock = std::function<double()>;
    ActionRecorder(Clock clock, QObject* parent = nullptr) : QObject(parent), clock_(std::move(clock)) {}
    bool start(const QString& path, QString* error);
    void stop();
    bool recording() const { return file_.isOpen(); }
    void record(const OperatorAction& action);

private:
    Clock clock_;
    QFile file_;
};

} // namespace m350::ui
