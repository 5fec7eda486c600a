#pragma once

#include <QElapsedTimer>
#include <QObject>

#include <functional>

class QTimer;

namespace m350::ui {

// The session's display clock on the wall clock: a frame on every 1/60 s boundary since it
// started (60 frames a second on average, not a 16 ms timer's 62.5), each handed the virtual
// seconds since the last one (wall time times `rate`).
class FrameClock : public QObject {
    Q_OBJECT
public:
    explicit FrameClock(QObject* parent = nullptr);
    void start(double rate, std::function<void(double seconds)> frame); // runs until deleted

private:
    void tick();
    void scheduleTick();

    QTimer* timer_;
    QElapsedTimer wall_;
    qint64 lastTickNs_ = 0;
    double rate_ = 1.0;
    std::function<void(double)> frame_;
};

} // namespace m350::ui
