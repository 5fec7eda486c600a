#include "ui/panel/HandwheelWidget.h"

#include "ui/i18n/PanelText.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>

namespace m350::ui {

namespace {

constexpr double kDegreesPerDetent = 3.6; // 100 detents a turn, as an MPG has
constexpr int kFlushMs = 50;

} // namespace

HandwheelWidget::HandwheelWidget(Sink sink, QWidget* parent) : QWidget(parent), sink_(std::move(sink)) {
    setObjectName("handwheel");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    auto* axisRow = new QHBoxLayout;
    auto* stepRow = new QHBoxLayout;
    axes_ = new QButtonGroup(this);
    steps_ = new QButtonGroup(this);
    for (int axis = 0; axis < 5; ++axis) {
        auto* b = new QPushButton(PanelText::axis(axis), this);
        b->setObjectName(QStringLiteral("wheelAxis%1").arg(axis));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus);
        b->setChecked(axis == 0);
        axes_->addButton(b, axis);
        axisRow->addWidget(b);
    }
    for (int step : {1, 10, 100}) {
        auto* b = new QPushButton(QStringLiteral("x%1").arg(step), this);
        b->setObjectName(QStringLiteral("wheelStep%1").arg(step));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus);
        b->setChecked(step == 1);
        steps_->addButton(b, step);
        stepRow->addWidget(b);
    }
    connect(axes_, &QButtonGroup::idClicked, this, [this](int id) { select(id, -1); });
    connect(steps_, &QButtonGroup::idClicked, this, [this](int id) { select(-1, id); });
    column->addLayout(axisRow);
    column->addLayout(stepRow);
    column->addStretch(1);
    flushTimer_.setInterval(kFlushMs);
    connect(&flushTimer_, &QTimer::timeout, this, &HandwheelWidget::flush);
    setMinimumHeight(140);
}

void HandwheelWidget::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    for (int axis = 3; axis < 5; ++axis) {
        QAbstractButton* b = axes_->button(axis);
        const bool shown = s.axisShown[static_cast<std::size_t>(axis)];
        if (b->text() != PanelText::axis(axis, s)) {
            b->setText(PanelText::axis(axis, s));
        }
        b->setEnabled(shown);
        if (!shown && axis_ == axis) { // the machine no longer has it: the wheel goes back to X
            flush();
            axis_ = 0;
            axes_->button(0)->setChecked(true);
        }
    }
    bool guide = snapshot.status.guide;
    if (guide != guide_) {
        guide_ = guide;
        update();
    }
}

void HandwheelWidget::turn(int detents) {
    if (detents == 0) {
        return;
    }
    if (pending_ == 0 && !flushTimer_.isActive()) {
        sinceFlush_.start();
        flushTimer_.start();
    }
    pending_ += detents;
    dialAngle_ += detents * kDegreesPerDetent;
    update();
}

void HandwheelWidget::flush() {
    if (pending_ == 0) {
        flushTimer_.stop();
        return;
    }
    double seconds = sinceFlush_.isValid() ? sinceFlush_.elapsed() / 1000.0 : kFlushMs / 1000.0;
    sink_(OperatorAction::wheelTurn(axis_, step_, pending_, std::max(seconds, 0.001)));
    pending_ = 0;
    sinceFlush_.restart();
}

QRectF HandwheelWidget::dial() const {
    double top = 64;
    double size = std::max(40.0, std::min<double>(width(), height() - top) - 6);
    return QRectF((width() - size) / 2.0, top, size, size);
}

double HandwheelWidget::angleAt(const QPointF& point) const {
    QPointF c = dial().center();
    return std::atan2(point.y() - c.y(), point.x() - c.x()) * 180.0 / M_PI;
}

void HandwheelWidget::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    QRectF r = dial();
    p.setPen(QPen(palette().color(QPalette::Mid), 2));
    p.setBrush(guide_ ? QColor(70, 110, 70) : QColor(60, 60, 70));
    p.drawEllipse(r);
    p.setBrush(QColor(200, 200, 210));
    QPointF c = r.center();
    double radius = r.width() / 2.0 * 0.72;
    double a = dialAngle_ * M_PI / 180.0;
    p.drawEllipse(QPointF(c.x() + radius * std::cos(a), c.y() + radius * std::sin(a)), r.width() * 0.08,
                  r.width() * 0.08);
    p.setPen(palette().color(QPalette::BrightText));
    p.drawText(r, Qt::AlignCenter, QStringLiteral("MPG"));
}

void HandwheelWidget::wheelEvent(QWheelEvent* event) {
    int notches = event->angleDelta().y() / 120;
    turn(notches != 0 ? notches : (event->angleDelta().y() > 0 ? 1 : -1));
    event->accept();
}

void HandwheelWidget::mousePressEvent(QMouseEvent* event) {
    dragAngle_ = angleAt(event->position());
    event->accept();
}

void HandwheelWidget::mouseMoveEvent(QMouseEvent* event) {
    double angle = angleAt(event->position());
    double delta = std::remainder(angle - dragAngle_, 360.0);
    int detents = static_cast<int>(delta / kDegreesPerDetent);
    if (detents != 0) {
        dragAngle_ += detents * kDegreesPerDetent;
        turn(detents);
    }
    event->accept();
}

void HandwheelWidget::select(int axis, int step) {
    flush(); // detents turned so far belong to the old setting
    if (QAbstractButton* b = axis >= 0 ? axes_->button(axis) : nullptr) {
        b->setChecked(true);
        axis_ = axis;
    }
    if (QAbstractButton* b = step > 0 ? steps_->button(step) : nullptr) {
        b->setChecked(true);
        step_ = step;
    }
}

} // namespace m350::ui
