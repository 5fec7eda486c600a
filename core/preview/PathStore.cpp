#include "core/preview/PathStore.h"

#include "core/preview/ArcPoints.h"

#include <cmath>

namespace m350::preview {

PathStore::Chunk& PathStore::openChunk() {
    if (chunks_.empty() || chunks_.back().segments.size() == kChunkSegments) {
        if (!chunks_.empty()) {
            chunks_.back().arcs.shrink_to_fit(); // full: it never grows again
        }
        Chunk& chunk = chunks_.emplace_back();
        chunk.start = position_;
        chunk.segments.reserve(kChunkSegments);
        chunk.box.add(position_);
    }
    return chunks_.back();
}

void PathStore::add(const PathSegment& segment, const ArcCentre* centre, const Box& box) {
    Chunk& chunk = openChunk();
    chunk.segments.push_back(segment);
    if (centre) {
        chunk.arcs.push_back(*centre);
        ++arcCount_;
    }
    chunk.box.add(box);
    bounds_.add(box);
    position_ = segment.end;
    ++size_;
}

void PathStore::addLine(const PathSegment& segment) {
    Box box;
    box.add(position_);
    box.add(segment.end);
    length_ += std::hypot(segment.end.x - position_.x, segment.end.y - position_.y, segment.end.z - position_.z);
    add(segment, nullptr, box);
}

void PathStore::addArc(const PathSegment& segment, ArcCentre centre) {
    const PlanarArc arc(position_, segment, centre);
    length_ += std::hypot(arc.radius * arc.sweep, arc.endW - arc.startW);
    add(segment, &centre, arc.box());
}

std::uint16_t PathStore::fileIndex(const std::string& name) {
    for (std::size_t i = 0; i < files_.size(); ++i) {
        if (files_[i] == name) {
            return static_cast<std::uint16_t>(i);
        }
    }
    if (files_.size() == 0xFFFF) {
        return 0xFFFF; // more files than a preview names: the rest share the last index
    }
    files_.push_back(name);
    return static_cast<std::uint16_t>(files_.size() - 1);
}

std::size_t PathStore::bytes() const {
    std::size_t total = chunks_.capacity() * sizeof(Chunk);
    for (const Chunk& chunk : chunks_) {
        total += chunk.segments.capacity() * sizeof(PathSegment) + chunk.arcs.capacity() * sizeof(ArcCentre);
    }
    return total;
}

void PathStore::coarsen(double tolerance) {
    std::vector<Chunk> old = std::move(chunks_);
    chunks_.clear();
    const Point3 start = old.empty() ? position_ : old.front().start;
    position_ = start;
    size_ = 0;
    arcCount_ = 0;
    length_ = 0.0;
    // the path so far is kept; a point closer than `tolerance` to the last kept one is dropped,
    // unless the kind of move changes there (a rapid stays a rapid)
    Point3 kept = start;
    PathSegment pending{};
    bool hasPending = false;
    auto keep = [&](const PathSegment& s) {
        addLine(s);
        kept = s.end;
        hasPending = false;
    };
    auto offer = [&](const PathSegment& s) {
        if (hasPending && pending.kind != s.kind) {
            keep(pending);
        }
        const double d = std::hypot(s.end.x - kept.x, s.end.y - kept.y, s.end.z - kept.z);
        if (d >= tolerance) {
            keep(s);
        } else {
            pending = s;
            hasPending = true;
        }
    };
    for (Chunk& chunk : old) {
        Point3 at = chunk.start;
        std::size_t arc = 0;
        for (const PathSegment& s : chunk.segments) {
            if (s.arc()) {
                const PlanarArc planar(at, s, chunk.arcs[arc++]);
                const int n = planar.chords(tolerance);
                PathSegment piece = s;
                piece.kind = SegmentKind::Feed;
                for (int i = 1; i <= n; ++i) {
                    piece.end = i == n ? s.end : planar.at(double(i) / n);
                    offer(piece);
                }
            } else {
                offer(s);
            }
            at = s.end;
        }
        chunk = Chunk{}; // each old chunk freed once read: the store never holds both whole
    }
    if (hasPending) {
        keep(pending);
    }
}

} // namespace m350::preview
