#pragma once

#include "core/preview/PathSegment.h"

#include <cstddef>
#include <string>
#include <vector>

namespace m350::preview {

// A previewed path in chunks of a fixed size: a chunk never moves once full (no reallocation of
// a million moves while the preview grows), knows its box (a view skips the chunks it does not
// show) and where its first move starts (a view draws any chunk alone). Arc centres sit in the
// chunk beside its segments, in the order of its arcs.
class PathStore {
public:
    static constexpr std::size_t kChunkSegments = 4096;

    struct Chunk {
        Point3 start; // where the chunk's first move starts
        std::vector<PathSegment> segments;
        std::vector<ArcCentre> arcs;
        Box box; // of every point the chunk's moves pass (arcs by their extremes)
    };

    explicit PathStore(Point3 start = {}) : position_(start) {}

    // A straight move (Rapid or Feed) from where the path is to `segment.end`.
    void addLine(const PathSegment& segment);
    // An arc from where the path is to `segment.end` about `centre`.
    void addArc(const PathSegment& segment, ArcCentre centre);
    // Where the path is: the last move's end (or the start).
    Point3 position() const { return position_; }

    // The index of a file name in files(), added when new (a segment keeps 16 bits of it).
    std::uint16_t fileIndex(const std::string& name);
    const std::vector<std::string>& files() const { return files_; }

    const std::vector<Chunk>& chunks() const { return chunks_; }
    std::size_t size() const { return size_; }
    std::size_t arcCount() const { return arcCount_; }
    Box bounds() const { return bounds_; }
    // How long the path is, mm (an arc along its arc): a view level's tolerance from it.
    double length() const { return length_; }
    // Bytes the store holds (capacities, not sizes): what the budget counts.
    std::size_t bytes() const;

    // Merges moves so that no point the path passed is farther than `tolerance` mm from the new
    // path: runs of short moves become one, arcs become lines through points on them. The chunks
    // are rebuilt; the store shrinks (the segment budget of a huge program).
    void coarsen(double tolerance);

private:
    Chunk& openChunk();
    void add(const PathSegment& segment, const ArcCentre* centre, const Box& box);

    std::vector<Chunk> chunks_;
    std::vector<std::string> files_;
    Point3 position_;
    Box bounds_;
    std::size_t size_ = 0;
    std::size_t arcCount_ = 0;
    double length_ = 0.0;
};

} // namespace m350::preview
