#include "ui/view/ViewTransform.h"

#include <algorithm>

namespace m350::ui {

QRectF ViewTransform::visibleMm() const {
    const QPointF a = toMm({0.0, 0.0});
    const QPointF b = toMm({size_.width(), size_.height()});
    return QRectF(a, b).normalized();
}

void ViewTransform::fit(const QRectF& mm, double margin) {
    centre_ = mm.center();
    const double w = std::max(1.0, size_.width() - 2.0 * margin);
    const double h = std::max(1.0, size_.height() - 2.0 * margin);
    const double scale = std::max(mm.width() / w, mm.height() / h);
    mmPerPixel_ = std::clamp(scale > 0.0 ? scale : 1.0, kClosest, kFarthest);
}

void ViewTransform::zoomAt(QPointF px, double factor) {
    if (factor <= 0.0) {
        return;
    }
    const QPointF before = toMm(px);
    mmPerPixel_ = std::clamp(mmPerPixel_ / factor, kClosest, kFarthest);
    const QPointF after = toMm(px);
    centre_ += before - after;
}

void ViewTransform::pan(QPointF pixels) {
    centre_ += QPointF(-pixels.x() * mmPerPixel_, pixels.y() * mmPerPixel_);
}

} // namespace m350::ui
