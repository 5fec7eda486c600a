#pragma once

#include "ui/actions/OperatorAction.h"
#include "ui/session/PanelSnapshot.h"

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

#include <functional>

class QButtonGroup;

namespace m350::ui {

// The virtual handwheel (手轮, MPG): an axis switch X Y Z 4th 5th, a x1/x10/x100 switch and a dial
// turned with the mouse wheel, by dragging it round, or with Alt+Left / Alt+Right. Detents are gathered
// for a twentieth of a second and sent as one wheel action (axis, step, detents, seconds), so the
// machine sees the wheel's speed as a real MPG's pulse rate.
class HandwheelWidget : public QWidget {
    Q_OBJECT
public:
    using Sink = std::function<void(const OperatorAction&)>;
    explicit HandwheelWidget(Sink sink, QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    void turn(int detents); // from the keyboard
    void select(int axis, int step); // the switches from the keyboard; -1 leaves one as it is
    int axis() const { return axis_; }
    int step() const { return step_; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    QSize sizeHint() const override { return {220, 170}; }

private:
    void flush();
    QRectF dial() const;
    double angleAt(const QPointF& point) const;
    Sink sink_;
    int axis_ = 0;
    int step_ = 1;
    int pending_ = 0;
    double dialAngle_ = 0.0; // degrees, for drawing the turned dial
    double dragAngle_ = 0.0;
    QTimer flushTimer_;
    QElapsedTimer sinceFlush_;
    QButtonGroup* axes_;
    QButtonGroup* steps_;
    bool guide_ = false;
};

} // namespace m350::ui
