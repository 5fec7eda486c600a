#pragma once

#include "core/interp/CutterCompensation.h"

#include <Eigen/Core>

#include <vector>

// Plane geometry for CutterCompensation: offsets, tangents, intersections of offset pieces.
namespace m350::interp::ccgeom {

constexpr double kEps = 1e-9;

inline Eigen::Vector2d leftNormal(const Eigen::Vector2d& d) {
    return {-d.y(), d.x()};
}
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

bool isFullCircle(const PathSegment& arc);
double arcRadius(const PathSegment& arc);
// Radius of the offset arc; `signedRadius` is + on the left (G41), - on the right (G42).
double offsetArcRadius(const PathSegment& arc, double signedRadius);
// Unit direction of travel at `p`, a point of the segment.
Eigen::Vector2d tangentAt(const PathSegment& s, const Eigen::Vector2d& p);
Eigen::Vector2d offsetPoint(const PathSegment& s, const Eigen::Vector2d& p, double signedRadius);
// Counterclockwise (or clockwise) angle from `from` to `to` around `center`, in [0, 2 pi).
double sweep(const Eigen::Vector2d& center, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
             bool clockwise);

// A piece of an offset path: `seg` runs from the tool's start to the offset end; `direction` is the
// programmed line's direction, kept because a trimmed piece may have no length left.
struct OffsetPiece {
    PathSegment seg;
    Eigen::Vector2d direction = Eigen::Vector2d::Zero();
    bool fullCircle = false;
};

OffsetPiece offsetPiece(const PathSegment& programmed, const Eigen::Vector2d& toolStart, double signedRadius);
// Intersections of the carrying line or circle of each piece.
std::vector<Eigen::Vector2d> intersections(const OffsetPiece& a, const OffsetPiece& b);
// Whether `p`, a point of the carrying line or circle, lies between the piece's start and end.
bool contains(const OffsetPiece& piece, const Eigen::Vector2d& p);
// Appends the piece cut to end at `to`, unless nothing is left of it.
void appendPiece(std::vector<PathSegment>& out, const OffsetPiece& piece, const Eigen::Vector2d& to);
void appendLine(std::vector<PathSegment>& out, const Eigen::Vector2d& from, const Eigen::Vector2d& to);

} // namespace m350::interp::ccgeom
