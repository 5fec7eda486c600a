#pragma once

#include <QPointF>
#include <QRectF>
#include <QSizeF>

namespace m350::ui {

// The two views of the machine: from above (X right, Y up) and from the front (X right, Z up).
enum class ViewPlane { Top, Front };

// Machine X Y Z to the plane's two coordinates, mm.
inline QPointF project(ViewPlane plane, double x, double y, double z) {
    return plane == ViewPlane::Top ? QPointF(x, y) : QPointF(x, z);
}

// Where the millimetres of one plane land in a widget's pixels: the plane's point shown at the
// centre and the millimetres one pixel covers (the same both ways: nothing is stretched). The
// plane's second axis points up, the screen's down.
class ViewTransform {
public:
    void setSize(QSizeF pixels) { size_ = pixels; }
    QSizeF size() const { return size_; }
    double mmPerPixel() const { return mmPerPixel_; }
    QPointF centre() const { return centre_; }

    QPointF toPixel(QPointF mm) const {
        return {size_.width() / 2.0 + (mm.x() - centre_.x()) / mmPerPixel_,
                size_.height() / 2.0 - (mm.y() - centre_.y()) / mmPerPixel_};
    }
    QPointF toMm(QPointF px) const {
        return {centre_.x() + (px.x() - size_.width() / 2.0) * mmPerPixel_,
                centre_.y() - (px.y() - size_.height() / 2.0) * mmPerPixel_};
    }
    // The plane's rectangle the widget shows.
    QRectF visibleMm() const;

    // Shows all of `mm` (a plane rectangle), as large as fits with `margin` pixels around it.
    void fit(const QRectF& mm, double margin = 12.0);
    // Zooms by `factor` (> 1: closer) keeping the point under `px` where it is.
    void zoomAt(QPointF px, double factor);
    // Moves what is shown by `pixels` (a drag to the right shows what lay to the left).
    void pan(QPointF pixels);

    // Limits that keep the scale sane: a micron a pixel at the closest, 100 m at the farthest.
    static constexpr double kClosest = 1e-3;
    static constexpr double kFarthest = 1e5;

private:
    QSizeF size_{1.0, 1.0};
    QPointF centre_;
    double mmPerPixel_ = 1.0;
};

} // namespace m350::ui
