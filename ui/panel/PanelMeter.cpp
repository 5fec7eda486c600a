#include "ui/panel/PanelMeter.h"

#include <QEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QWidget>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>

namespace m350::ui {

qint64 steadyNowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double processCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

PanelMeter::PanelMeter(QWidget* screen, qint64 processStartNs, QObject* parent)
    : QObject(parent), processStartNs_(processStartNs) {
    screen->installEventFilter(this);
}

void PanelMeter::onSnapshot(const SnapshotPtr& snapshot) { latestPublishedNs_ = snapshot->publishedNs; }

void PanelMeter::begin() {
    counting_ = true;
    frames_ = 0;
    latenciesMs_.clear();
    wall_.start();
    cpuAtBegin_ = processCpuSeconds();
}

bool PanelMeter::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Paint) {
        qint64 now = steadyNowNs();
        if (firstPaintNs_ == 0) {
            firstPaintNs_ = now;
        }
        if (counting_ && latestPublishedNs_ != paintedPublishedNs_) {
            // a frame showing a snapshot not painted before: its age is the display latency
            ++frames_;
            latenciesMs_.push_back(static_cast<double>(now - latestPublishedNs_) * 1e-6);
            paintedPublishedNs_ = latestPublishedNs_;
        }
    }
    return QObject::eventFilter(watched, event);
}

QString PanelMeter::reportJson() const {
    double seconds = std::max(1e-9, static_cast<double>(wall_.nsecsElapsed()) * 1e-9);
    QVector<double> sorted = latenciesMs_;
    std::sort(sorted.begin(), sorted.end());
    auto percentile = [&sorted](double p) {
        return sorted.isEmpty() ? 0.0 : sorted[static_cast<int>(p * static_cast<double>(sorted.size() - 1))];
    };
    QJsonObject out{{"startup_ms", static_cast<double>(firstPaintNs_ - processStartNs_) * 1e-6},
                    {"seconds", seconds},
                    {"frames_per_second", frames_ / seconds},
                    {"cpu_percent_of_one_core", 100.0 * (processCpuSeconds() - cpuAtBegin_) / seconds},
                    {"latency_ms_median", percentile(0.5)},
                    {"latency_ms_p99", percentile(0.99)},
                    {"frame_ms", 1000.0 / 60.0}};
    return QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact));
}

} // namespace m350::ui
