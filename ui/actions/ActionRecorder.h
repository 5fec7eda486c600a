#pragma once

#include "ui/actions/OperatorAction.h"

#include <QObject>
#include <QString>

#include <filesystem>
#include <functional>

namespace m350::ui {

// Writes what the operator does to a replay file (JSON Lines, one action a line, `t` = the
// machine's virtual time when it happened), so a session can be played back with --replay.
// A regular file is not truncated: the lines go to a temp file beside it, which replaces it at the
// first action (then grows in place, so a session that ends at any moment leaves what was done);
// a device or FIFO is written as one. A write that fails stops the recording and says why.
class ActionRecorder : public QObject {
    Q_OBJECT
public:
    using Clock = std::function<double()>;
    ActionRecorder(Clock clock, QObject* parent = nullptr) : QObject(parent), clock_(std::move(clock)) {}
    ~ActionRecorder() override;
    bool start(const QString& path, QString* error);
    // Ends the recording; empty when every line reached the file, else why not (also after failed()).
    QString stop();
    bool recording() const { return fd_ >= 0; }
    void record(const OperatorAction& action);
    // What a line of an action is (default: its JSON): a training attempt chains every line
    // (ui/training/AttemptFile.h); an empty line is not written.
    using Format = std::function<QByteArray(const OperatorAction&)>;
    void setFormat(Format format) { format_ = std::move(format); }
    // A line of the caller's own (an attempt's first line and its hand-in), written as an action's is.
    bool writeExtra(const QByteArray& line);

signals:
    void failed(const QString& why); // a write failed: the recording stopped

private:
    bool publish(); // the temp file replaces the target
    bool writeLine(const QByteArray& line);
    void fail(const QString& why);
    Clock clock_;
    Format format_;
    int fd_ = -1;
    QString path_;                 // as the operator named it
    std::filesystem::path target_; // where it goes (a link's file)
    std::filesystem::path temp_;   // empty once published, or for a device
    QString error_;
};

} // namespace m350::ui
