#include "core/preview/PathLevels.h"

#include "core/preview/ArcPoints.h"

#include <cmath>

namespace m350::preview {

namespace {

constexpr std::size_t kChunkPoints = 4096;

// Fills a level from a stream of points (`offer`), dropping those closer than its tolerance.
class LevelWriter {
public:
    LevelWriter(PathLevels::Level& level, Point3 start) : level_(level), kept_(start) {}

    void offer(const Point3& p, std::uint32_t tag) {
        if (hasPending_ && (pendingTag_ & PathLevels::Point::kRapid) != (tag & PathLevels::Point::kRapid)) {
            keep(pending_, pendingTag_);
        }
        const double d = std::hypot(p.x - kept_.x, p.y - kept_.y, p.z - kept_.z);
        if (d >= level_.tolerance) {
            keep(p, tag);
        } else {
            pending_ = p;
            pendingTag_ = tag;
            hasPending_ = true;
        }
    }

    void finish() {
        if (hasPending_) {
            keep(pending_, pendingTag_);
        }
        for (PathLevels::Chunk& chunk : level_.chunks) {
            chunk.points.shrink_to_fit();
        }
    }

private:
    void keep(const Point3& p, std::uint32_t tag) {
        if (level_.chunks.empty() || level_.chunks.back().points.size() == kChunkPoints) {
            PathLevels::Chunk& chunk = level_.chunks.emplace_back();
            chunk.start = kept_;
            chunk.box.add(kept_);
        }
        PathLevels::Chunk& chunk = level_.chunks.back();
        chunk.points.push_back({p, tag});
        chunk.box.add(p);
        ++level_.size;
        kept_ = p;
        hasPending_ = false;
    }

    PathLevels::Level& level_;
    Point3 kept_;
    Point3 pending_{};
    std::uint32_t pendingTag_ = 0;
    bool hasPending_ = false;
};

PathLevels::Level fromStore(const PathStore& store, double tolerance) {
    PathLevels::Level level;
    level.tolerance = tolerance;
    if (store.chunks().empty()) {
        return level;
    }
    LevelWriter writer(level, store.chunks().front().start);
    std::uint32_t index = 0;
    for (const PathStore::Chunk& chunk : store.chunks()) {
        Point3 at = chunk.start;
        std::size_t arc = 0;
        for (const PathSegment& s : chunk.segments) {
            if (s.arc()) {
                const PlanarArc planar(at, s, chunk.arcs[arc++]);
                const int n = planar.chords(tolerance / 2.0);
                for (int i = 1; i < n; ++i) {
                    writer.offer(planar.at(double(i) / n), index);
                }
            }
            writer.offer(s.end, index | (s.kind == SegmentKind::Rapid ? PathLevels::Point::kRapid : 0U));
            at = s.end;
            ++index;
        }
    }
    writer.finish();
    return level;
}

PathLevels::Level fromLevel(const PathLevels::Level& below, double tolerance) {
    PathLevels::Level level;
    level.tolerance = tolerance;
    if (below.chunks.empty()) {
        return level;
    }
    LevelWriter writer(level, below.chunks.front().start);
    for (const PathLevels::Chunk& chunk : below.chunks) {
        for (const PathLevels::Point& p : chunk.points) {
            writer.offer(p.at, p.tag);
        }
    }
    writer.finish();
    return level;
}

} // namespace

PathLevels PathLevels::build(const PathStore& store, std::size_t smallest) {
    PathLevels levels;
    const Box box = store.bounds();
    if (box.empty() || store.size() < smallest) {
        return levels;
    }
    const double diagonal =
        std::hypot(box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z);
    // the finest level: a 4096-pixel view of the whole path loses nothing in it; and no finer
    // than a quarter of the moves would need (a level keeps about length / tolerance points), so
    // a dense path does not pass over its moves again and again for levels that keep too many
    double tolerance = std::max({diagonal / 8192.0, 1e-4, 4.0 * store.length() / double(store.size())});
    std::size_t below = store.size();
    while (tolerance < diagonal) {
        Level level = levels.levels_.empty() ? fromStore(store, tolerance) : fromLevel(levels.levels_.back(), tolerance);
        if (level.size * 4 <= below) {
            below = level.size;
            levels.levels_.push_back(std::move(level));
            if (below < smallest) {
                break;
            }
        }
        tolerance *= 2.0;
    }
    return levels;
}

const PathLevels::Level* PathLevels::forScale(double mmPerPixel) const {
    const Level* best = nullptr;
    for (const Level& level : levels_) {
        if (level.tolerance <= mmPerPixel / 2.0) {
            best = &level;
        }
    }
    return best;
}

std::size_t PathLevels::bytes() const {
    std::size_t total = levels_.capacity() * sizeof(Level);
    for (const Level& level : levels_) {
        total += level.chunks.capacity() * sizeof(Chunk);
        for (const Chunk& chunk : level.chunks) {
            total += chunk.points.capacity() * sizeof(Point);
        }
    }
    return total;
}

} // namespace m350::preview
