#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

namespace m350::preview {

enum class SegmentKind : std::uint8_t { Rapid, Feed, ArcCw, ArcCcw };
enum class ArcPlane : std::uint8_t { XY, ZX, YZ }; // G17 G18 G19, as machine::Plane

struct Point3 {
    float x = 0.0F;
    float y = 0.0F;
    float z = 0.0F;
};

// A box in machine coordinates; empty until a point is added.
struct Box {
    Point3 min{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    Point3 max{std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
               std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x; }
    void add(const Point3& p) {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
    void add(const Box& b) {
        if (!b.empty()) {
            add(b.min);
            add(b.max);
        }
    }
};

// One move of a previewed path: where it ends (machine coordinates, mm; floats keep 0.1 um at a
// metre) and the line that made it. 20 bytes, so a million moves take 20 MB; an arc's centre is
// kept beside it (ArcCentre, 8 bytes), the start is the move before's end.
struct PathSegment {
    Point3 end;
    std::uint32_t line = 0; // 1-based, in `file`
    std::uint16_t file = 0; // PathStore::files()
    SegmentKind kind = SegmentKind::Feed;
    ArcPlane plane = ArcPlane::XY;

    bool arc() const { return kind == SegmentKind::ArcCw || kind == SegmentKind::ArcCcw; }
};
static_assert(sizeof(PathSegment) == 20);

// An arc's centre in its plane: (x, y) for XY, (z, x) for ZX, (y, z) for YZ; the third coordinate
// runs linearly from start to end (a helix).
struct ArcCentre {
    float u = 0.0F;
    float v = 0.0F;
};

} // namespace m350::preview
