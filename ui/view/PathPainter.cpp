#include "ui/view/PathPainter.h"

#include "core/preview/ArcPoints.h"

#include <QLineF>
#include <QPainter>
#include <QVector>

#include <algorithm>
#include <cmath>

namespace m350::ui {

namespace {

using preview::Point3;

QPointF on(ViewPlane plane, const Point3& p) { return project(plane, p.x, p.y, p.z); }

QRectF planeBox(ViewPlane plane, const preview::Box& box) {
    return QRectF(on(plane, box.min), on(plane, box.max)).normalized();
}

// Whether a chunk's box lies in the visible rectangle (a box of no width still counts).
bool shows(const QRectF& visible, const QRectF& box) {
    return box.right() >= visible.left() && box.left() <= visible.right() && box.bottom() >= visible.top() &&
           box.top() <= visible.bottom();
}

// Calls f(from, to) in pixels for each straight piece of move `s` that starts at `start`.
template <class F>
void pieces(const preview::PathSegment& s, const Point3& start, const preview::ArcCentre* centre, ViewPlane plane,
            const ViewTransform& view, F&& f) {
    if (!s.arc() || !centre) {
        f(view.toPixel(on(plane, start)), view.toPixel(on(plane, s.end)));
        return;
    }
    const preview::PlanarArc arc(start, s, *centre);
    const int n = std::min(arc.chords(view.mmPerPixel() / 2.0), 256);
    QPointF last = view.toPixel(on(plane, start));
    for (int i = 1; i <= n; ++i) {
        const QPointF next = view.toPixel(on(plane, i == n ? s.end : arc.at(double(i) / n)));
        f(last, next);
        last = next;
    }
}


// The moves or points of the chunks in view: what a frame would draw.
template <class Chunks, class Size>
std::size_t inView(const Chunks& chunks, ViewPlane plane, const QRectF& visible, Size size) {
    std::size_t n = 0;
    for (const auto& chunk : chunks) {
        if (shows(visible, planeBox(plane, chunk.box))) {
            n += size(chunk);
        }
    }
    return n;
}

} // namespace

// The level for the scale (PathLevels::forScale), or a coarser one while the one for the scale
// would draw more than kMostLines in view: a path far denser than the pixels (a CAM raster seen
// whole, a kilometre of moves in 200 mm) fills its area either way, and a frame stays in its 16 ms.
const preview::PathLevels::Level* PathPainter::levelFor(const preview::Preview& preview, ViewPlane plane,
                                                         const ViewTransform& view, const QRectF& visible) {
    const auto& levels = preview.levels.levels();
    const preview::PathLevels::Level* level = preview.levels.forScale(view.mmPerPixel());
    std::size_t index = level ? std::size_t(level - levels.data()) : 0;
    if (!level) {
        const std::size_t moves =
            inView(preview.path.chunks(), plane, visible, [](const preview::PathStore::Chunk& c) { return c.segments.size(); });
        if (moves <= kMostLines || levels.empty()) {
            return nullptr;
        }
        level = &levels.front();
    }
    while (index + 1 < levels.size() &&
           inView(level->chunks, plane, visible, [](const preview::PathLevels::Chunk& c) { return c.points.size(); }) > kMostLines) {
        level = &levels[++index];
    }
    return level;
}

// The lines of a frame by pen; a line wholly to one side of the pixels shown is left out (a chunk
// partly in view brings all its moves).
struct LineBuckets {
    explicit LineBuckets(QSizeF size) : right(size.width() + 2.0), bottom(size.height() + 2.0) {}
    QVector<QLineF> feed, rapid, doneFeed, doneRapid;
    double left = -2.0, top = -2.0, right, bottom;
    void add(bool rapidMove, bool done, QPointF a, QPointF b) {
        if ((a.x() < left && b.x() < left) || (a.x() > right && b.x() > right) || (a.y() < top && b.y() < top) ||
            (a.y() > bottom && b.y() > bottom)) {
            return;
        }
        (done ? (rapidMove ? doneRapid : doneFeed) : (rapidMove ? rapid : feed)).append(QLineF(a, b));
    }
    std::size_t size() const { return std::size_t(feed.size() + rapid.size() + doneFeed.size() + doneRapid.size()); }
};


std::size_t PathPainter::paint(QPainter& painter, const preview::Preview& preview, ViewPlane plane, const ViewTransform& view,
                               std::size_t done, const Colours& colours) {
    const QRectF visible = view.visibleMm().adjusted(-view.mmPerPixel(), -view.mmPerPixel(), view.mmPerPixel(), view.mmPerPixel());
    LineBuckets lines(view.size());
    if (const preview::PathLevels::Level* level = levelFor(preview, plane, view, visible)) {
        for (const preview::PathLevels::Chunk& chunk : level->chunks) {
            if (!shows(visible, planeBox(plane, chunk.box))) {
                continue;
            }
            QPointF last = view.toPixel(on(plane, chunk.start));
            for (const preview::PathLevels::Point& p : chunk.points) {
                const QPointF next = view.toPixel(on(plane, p.at));
                lines.add(p.rapid(), p.segment() < done, last, next);
                last = next;
            }
        }
    } else {
        std::size_t index = 0;
        for (const preview::PathStore::Chunk& chunk : preview.path.chunks()) {
            if (!shows(visible, planeBox(plane, chunk.box))) {
                index += chunk.segments.size();
                continue;
            }
            Point3 at = chunk.start;
            std::size_t arc = 0;
            for (const preview::PathSegment& s : chunk.segments) {
                const preview::ArcCentre* centre = s.arc() ? &chunk.arcs[arc++] : nullptr;
                const bool rapid = s.kind == preview::SegmentKind::Rapid;
                const bool isDone = index < done;
                pieces(s, at, centre, plane, view, [&](QPointF a, QPointF b) { lines.add(rapid, isDone, a, b); });
                at = s.end;
                ++index;
            }
        }
    }
    drawBuckets(painter, lines, colours);
    return lines.size();
}

std::size_t PathPainter::paintDone(QPainter& painter, const preview::PathStore& path, ViewPlane plane, const ViewTransform& view,
                                   std::size_t from, std::size_t to, const Colours& colours) {
    LineBuckets lines(view.size());
    const std::size_t per = preview::PathStore::kChunkSegments;
    for (std::size_t c = from / per; c < path.chunks().size() && c * per < to; ++c) {
        const preview::PathStore::Chunk& chunk = path.chunks()[c];
        Point3 at = chunk.start;
        std::size_t arc = 0;
        for (std::size_t i = 0; i < chunk.segments.size() && c * per + i < to; ++i) {
            const preview::PathSegment& s = chunk.segments[i];
            const preview::ArcCentre* centre = s.arc() ? &chunk.arcs[arc++] : nullptr;
            if (c * per + i >= from) {
                const bool rapid = s.kind == preview::SegmentKind::Rapid;
                pieces(s, at, centre, plane, view, [&](QPointF a, QPointF b) { lines.add(rapid, true, a, b); });
            }
            at = s.end;
        }
    }
    drawBuckets(painter, lines, colours);
    return lines.size();
}

void PathPainter::drawBuckets(QPainter& painter, const LineBuckets& lines, const Colours& colours) {
    // few lines: smooth and a little wide; many: plain one-pixel lines (the raster engine's fast
    // path), to keep a frame within its 16 ms
    const bool many = lines.size() >= 20000;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, !many);
    const auto draw = [&](const QVector<QLineF>& bucket, const QColor& colour, Qt::PenStyle style, double width) {
        if (!bucket.isEmpty()) {
            QPen pen(colour, many ? 0.0 : width, style);
            pen.setCosmetic(true);
            painter.setPen(pen);
            painter.drawLines(bucket);
        }
    };
    draw(lines.rapid, colours.rapid, Qt::DashLine, 1.0);
    draw(lines.doneRapid, colours.doneRapid, Qt::DashLine, 1.0);
    draw(lines.feed, colours.feed, Qt::SolidLine, 1.4);
    draw(lines.doneFeed, colours.doneFeed, Qt::SolidLine, 1.6);
    painter.restore();
}

void PathPainter::paintMove(QPainter& painter, const preview::PathStore& path, std::size_t index, ViewPlane plane,
                            const ViewTransform& view) {
    if (index >= path.size()) {
        return;
    }
    const std::size_t per = preview::PathStore::kChunkSegments;
    const preview::PathStore::Chunk& chunk = path.chunks()[index / per];
    const std::size_t i = index % per;
    const Point3 start = i == 0 ? chunk.start : chunk.segments[i - 1].end;
    const preview::PathSegment& s = chunk.segments[i];
    const preview::ArcCentre* centre = nullptr;
    if (s.arc()) {
        const auto arcsBefore = std::count_if(chunk.segments.begin(), chunk.segments.begin() + std::ptrdiff_t(i),
                                              [](const preview::PathSegment& m) { return m.arc(); });
        centre = &chunk.arcs[std::size_t(arcsBefore)];
    }
    pieces(s, start, centre, plane, view, [&](QPointF a, QPointF b) { painter.drawLine(a, b); });
}

std::optional<std::size_t> PathPainter::hit(const preview::PathStore& path, ViewPlane plane, const ViewTransform& view,
                                            QPointF at, double radius) {
    const QPointF mm = view.toMm(at);
    const double reach = radius * view.mmPerPixel();
    const QRectF near(mm.x() - reach, mm.y() - reach, 2 * reach, 2 * reach);
    std::optional<std::size_t> best;
    double bestDistance = radius;
    std::size_t index = 0;
    for (const preview::PathStore::Chunk& chunk : path.chunks()) {
        if (!shows(near, planeBox(plane, chunk.box))) {
            index += chunk.segments.size();
            continue;
        }
        Point3 from = chunk.start;
        std::size_t arc = 0;
        for (const preview::PathSegment& s : chunk.segments) {
            const preview::ArcCentre* centre = s.arc() ? &chunk.arcs[arc++] : nullptr;
            pieces(s, from, centre, plane, view, [&](QPointF a, QPointF b) {
                const QPointF d = b - a;
                const double length2 = QPointF::dotProduct(d, d);
                const double t = length2 > 0.0 ? std::clamp(QPointF::dotProduct(at - a, d) / length2, 0.0, 1.0) : 0.0;
                const QPointF p = a + t * d - at;
                const double distance = std::hypot(p.x(), p.y());
                if (distance <= bestDistance) { // the later of two moves on one another: the one drawn on top
                    bestDistance = distance;
                    best = index;
                }
            });
            from = s.end;
            ++index;
        }
    }
    return best;
}

} // namespace m350::ui
