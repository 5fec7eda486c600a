#pragma once

#include "core/preview/PathStore.h"

#include <cstdint>
#include <vector>

namespace m350::preview {

// Coarser copies of a path for a view that shows it small. Level k keeps a point only where it
// lies at least tolerance(k) from the point kept before it (a change between rapid and feed is
// always kept; arcs become chords within the tolerance), so a view at a scale where tolerance(k)
// is under half a pixel draws level k and looks as if it drew every move, with a bounded number
// of lines: about the path's length on screen in pixels. Each level is at most a quarter of the
// one below it, so all of them together take under a third of the store's points.
class PathLevels {
public:
    struct Point {
        Point3 at;
        // The store's index of the move this point ends or lies on (a view colours what a run has
        // done by it), and whether that move is a rapid in the top bit.
        std::uint32_t tag = 0;

        static constexpr std::uint32_t kRapid = 0x8000'0000U;
        bool rapid() const { return (tag & kRapid) != 0; }
        std::size_t segment() const { return tag & ~kRapid; }
    };
    struct Chunk {
        Point3 start;
        std::vector<Point> points;
        Box box;
    };
    struct Level {
        double tolerance = 0.0; // mm
        std::vector<Chunk> chunks;
        std::size_t size = 0;
    };

    // Builds levels until one has fewer than `smallest` points.
    static PathLevels build(const PathStore& store, std::size_t smallest = 20000);

    // The coarsest level whose tolerance is at most half of `mmPerPixel`; nullptr when the store
    // itself must be drawn (the view is close enough to see every move).
    const Level* forScale(double mmPerPixel) const;
    const std::vector<Level>& levels() const { return levels_; }
    std::size_t bytes() const;

private:
    std::vector<Level> levels_;
};

} // namespace m350::preview
