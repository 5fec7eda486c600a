#include "ui/session/FrameClock.h"

#include <QTimer>

namespace m350::ui {

namespace {

constexpr qint64 kFrameNs = 1'000'000'000 / 60; // the display's 60 Hz

} // namespace

FrameClock::FrameClock(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setTimerType(Qt::PreciseTimer);
    timer_->setSingleShot(true);
    connect(timer_, &QTimer::timeout, this, &FrameClock::tick);
}

void FrameClock::start(double rate, std::function<void(double seconds)> frame) {
    rate_ = rate;
    frame_ = std::move(frame);
    wall_.start();
    lastTickNs_ = 0;
    scheduleTick();
}

void FrameClock::tick() {
    const qint64 now = wall_.nsecsElapsed();
    const double seconds = static_cast<double>(now - lastTickNs_) * 1e-9 * rate_;
    lastTickNs_ = now;
    frame_(seconds);
    scheduleTick();
}

void FrameClock::scheduleTick() {
    const qint64 now = wall_.nsecsElapsed();
    const qint64 next = (now / kFrameNs + 1) * kFrameNs;
    timer_->start(static_cast<int>((next - now + 999'999) / 1'000'000));
}

} // namespace m350::ui
