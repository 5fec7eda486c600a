#include "ui/program/PathView.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace m350::ui {

PathView::PathView(QWidget* parent) : QWidget(parent) {
    setObjectName("pathView");
    setMinimumSize(160, 120);
}

void PathView::clear() {
    path_ = {};
    drawn_ = 0;
    bounds_ = {};
    image_ = {};
    update();
}

void PathView::setPath(const SimulationPath& path) {
    if (path.size < drawn_) {
        clear();
    }
    path_ = path;
    if (path_.size == drawn_) {
        return;
    }
    bool rescale = bounds_.isEmpty();
    path_.forEach(drawn_, [&](const PathPoint& p) { rescale = rescale || !fits(p); });
    if (rescale) {
        redrawAll();
    } else {
        drawFrom(drawn_);
    }
    update();
}

void PathView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    redrawAll();
}

QPointF PathView::toScreen(const PathPoint& p) const {
    const double scale = std::min((width() - 8) / bounds_.width(), (height() - 8) / bounds_.height());
    const QPointF centre(width() / 2.0, height() / 2.0);
    return {centre.x() + (p.x - bounds_.center().x()) * scale, centre.y() - (p.y - bounds_.center().y()) * scale};
}

// A new scale: the path's box and a margin of 15 % around it, so growth seldom forces another.
void PathView::redrawAll() {
    image_ = QImage(size().expandedTo({1, 1}), QImage::Format_RGB32);
    image_.fill(QColor("#060a10"));
    drawn_ = 0;
    if (path_.size == 0) {
        bounds_ = {};
        return;
    }
    double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
    path_.forEach(0, [&](const PathPoint& p) {
        minX = std::min(minX, double(p.x));
        maxX = std::max(maxX, double(p.x));
        minY = std::min(minY, double(p.y));
        maxY = std::max(maxY, double(p.y));
    });
    const double side = std::max({maxX - minX, maxY - minY, 1.0});
    const QPointF centre((minX + maxX) / 2.0, (minY + maxY) / 2.0);
    bounds_ = QRectF(centre.x() - 0.65 * side, centre.y() - 0.65 * side, 1.3 * side, 1.3 * side);
    drawFrom(0);
}

void PathView::drawFrom(std::size_t first) {
    QPainter painter(&image_);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPen feed(QColor("#7cf07c"), 1.4);
    QPen rapid(QColor("#c0a040"), 1.0, Qt::DashLine);
    std::size_t index = first;
    path_.forEach(first, [&](const PathPoint& p) {
        if (index > 0) {
            painter.setPen(p.rapid ? rapid : feed);
            painter.drawLine(toScreen(last_), toScreen(p));
        }
        last_ = p;
        ++index;
    });
    drawn_ = index;
}

void PathView::paintEvent(QPaintEvent* event) {
    (void)event;
    QPainter painter(this);
    painter.drawImage(0, 0, image_);
    if (drawn_ > 0) {
        QPointF at = toScreen(last_);
        painter.setPen(QPen(QColor("#ff6060"), 2.0));
        painter.drawLine(at + QPointF(-6, 0), at + QPointF(6, 0));
        painter.drawLine(at + QPointF(0, -6), at + QPointF(0, 6));
    }
    painter.setPen(QColor("#7a8598"));
    painter.drawText(rect().adjusted(4, 2, -4, -2), Qt::AlignLeft | Qt::AlignTop, QStringLiteral("XY"));
}

} // namespace m350::ui
