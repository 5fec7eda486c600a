#pragma once

#include "ui/view/ViewTransform.h"

#include "core/preview/PreviewBuilder.h"

#include <QColor>

#include <cstddef>
#include <optional>

class QPainter;

namespace m350::ui {

// Draws a preview's path in one plane: feeds solid, rapids dashed, arcs as arcs (chords under
// half a pixel), the moves a run has done in their own colours. Far out it draws the coarsest
// level (core/preview/PathLevels.h) that still looks exact, so a frame draws about as many lines
// as the path is long in pixels, whatever the program's size; chunks off screen are skipped.
struct PathColours {
    QColor feed{0x7c, 0xf0, 0x7c};
    QColor rapid{0xc0, 0xa0, 0x40};
    QColor doneFeed{0x4a, 0x9a, 0xff};
    QColor doneRapid{0x5a, 0x70, 0x98};
};

struct LineBuckets;

class PathPainter {
public:
    using Colours = PathColours;

    // Moves before `done` are the run's; returns how many lines were drawn.
    static std::size_t paint(QPainter& painter, const preview::Preview& preview, ViewPlane plane, const ViewTransform& view,
                             std::size_t done, const Colours& colours = {});
    // Draws moves [from, to) in the colours of the run's part, over what is drawn: a frame while a
    // run goes on adds only what it did since the last one.
    static std::size_t paintDone(QPainter& painter, const preview::PathStore& path, ViewPlane plane, const ViewTransform& view,
                                 std::size_t from, std::size_t to, const Colours& colours = {});
    // Draws move `index` (all of its chords) with the painter's pen: a highlighted block.
    static void paintMove(QPainter& painter, const preview::PathStore& path, std::size_t index, ViewPlane plane,
                          const ViewTransform& view);

    // The move drawn nearest to pixel `at`, within `radius` pixels.
    static std::optional<std::size_t> hit(const preview::PathStore& path, ViewPlane plane, const ViewTransform& view,
                                          QPointF at, double radius);
    // The most lines a frame draws of a path before it takes a coarser level (about 5 ms).
    static constexpr std::size_t kMostLines = 100'000;

private:
    static const preview::PathLevels::Level* levelFor(const preview::Preview& preview, ViewPlane plane,
                                                      const ViewTransform& view, const QRectF& visible);
    static void drawBuckets(QPainter& painter, const LineBuckets& lines, const Colours& colours);

public:
    static const preview::PathSegment& segment(const preview::PathStore& path, std::size_t index) {
        return path.chunks()[index / preview::PathStore::kChunkSegments].segments[index % preview::PathStore::kChunkSegments];
    }
};

} // namespace m350::ui
