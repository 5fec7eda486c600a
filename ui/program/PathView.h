#pragma once

#include "ui/session/SimulationView.h"

#include <QImage>
#include <QRectF>
#include <QWidget>

namespace m350::ui {

// The simulated tool path seen from above (XY, machine coordinates): feeds solid, rapids dashed
// and dim, the tool's place a cross. It grows as the simulation runs: new segments are drawn onto
// a kept image, and the whole path again only when it leaves the scale (a margin of 15 % is kept) or
// the widget is resized.
class PathView : public QWidget {
    Q_OBJECT
public:
    explicit PathView(QWidget* parent = nullptr);
    void setPath(const SimulationPath& path); // the snapshot's; shared, not copied
    void clear();
    std::size_t drawnPoints() const { return drawn_; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void redrawAll();
    void drawFrom(std::size_t first);
    bool fits(const PathPoint& p) const { return bounds_.contains(p.x, p.y); }
    QPointF toScreen(const PathPoint& p) const;

    SimulationPath path_;
    QImage image_;
    QRectF bounds_;    // machine XY the image shows
    std::size_t drawn_ = 0;
    PathPoint last_{};
};

} // namespace m350::ui
