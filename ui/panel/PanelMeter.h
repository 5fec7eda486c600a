#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QElapsedTimer>
#include <QObject>
#include <QVector>

namespace m350::ui {

// Measures what the operator sees (m350-hmi --measure): how often the screen repaints, how long a
// snapshot takes from the worker to a painted screen, the process's CPU time, and the time from
// start to the first painted window.
class PanelMeter : public QObject {
    Q_OBJECT
public:
    // `screen`: the widget whose paints count as frames (the DRO); `processStartNs`: steady clock
    // at the start of main().
    PanelMeter(QWidget* screen, qint64 processStartNs, QObject* parent = nullptr);
    void onSnapshot(const SnapshotPtr& snapshot);
    void begin(); // start counting (after start-up)
    QString reportJson() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    qint64 processStartNs_;
    qint64 firstPaintNs_ = 0;
    qint64 latestPublishedNs_ = 0;
    qint64 paintedPublishedNs_ = 0;
    bool counting_ = false;
    int frames_ = 0;
    QVector<double> latenciesMs_;
    QElapsedTimer wall_;
    double cpuAtBegin_ = 0.0;
};

double processCpuSeconds();
qint64 steadyNowNs();

} // namespace m350::ui
