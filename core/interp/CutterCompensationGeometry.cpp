#include "core/interp/CutterCompensationGeometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace m350::interp::ccgeom {

using Eigen::Vector2d;

bool isFullCircle(const PathSegment& arc) {
    return arc.kind == PathSegment::Kind::Arc && (arc.end - arc.start).norm() <= kEps;
}

double arcRadius(const PathSegment& arc) {
    return (arc.start - arc.center).norm();
}

double offsetArcRadius(const PathSegment& arc, double signedRadius) {
    return arcRadius(arc) + (arc.clockwise ? signedRadius : -signedRadius);
}

Vector2d tangentAt(const PathSegment& s, const Vector2d& p) {
    if (s.kind == PathSegment::Kind::Line) {
        return (s.end - s.start).normalized();
    }
    const Vector2d ccw = leftNormal((p - s.center).normalized());
    return s.clockwise ? Vector2d(-ccw) : ccw;
}

Vector2d offsetPoint(const PathSegment& s, const Vector2d& p, double signedRadius) {
    return p + signedRadius * leftNormal(tangentAt(s, p));
}

double sweep(const Vector2d& center, const Vector2d& from, const Vector2d& to, bool clockwise) {
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    const double a0 = std::atan2(from.y() - center.y(), from.x() - center.x());
    const double a1 = std::atan2(to.y() - center.y(), to.x() - center.x());
    double d = std::fmod(clockwise ? a0 - a1 : a1 - a0, kTwoPi);
    if (d < 0.0) {
        d += kTwoPi;
    }
    return d >= kTwoPi ? 0.0 : d;
}

OffsetPiece offsetPiece(const PathSegment& programmed, const Vector2d& toolStart, double signedRadius) {
    OffsetPiece piece;
    piece.seg = programmed;
    piece.seg.start = toolStart;
    piece.seg.end = offsetPoint(programmed, programmed.end, signedRadius);
    if (programmed.kind == PathSegment::Kind::Line) {
        piece.direction = tangentAt(programmed, programmed.start);
    } else {
        piece.fullCircle = isFullCircle(programmed);
    }
    return piece;
}

namespace {

std::vector<Vector2d> lineLine(const Vector2d& p, const Vector2d& u, const Vector2d& q, const Vector2d& v) {
    const double denom = cross(u, v);
    if (std::abs(denom) <= kEps) {
        return {};
    }
    return {p + (cross(q - p, v) / denom) * u};
}

std::vector<Vector2d> lineCircle(const Vector2d& p, const Vector2d& u, const Vector2d& c, double r) {
    const Vector2d w = p - c;
    const double b = u.dot(w);
    double disc = b * b - (w.squaredNorm() - r * r);
    if (disc < -kEps * r) {
        return {};
    }
    // Tangency shows up as a slightly negative discriminant after rounding.
    disc = std::sqrt(std::max(disc, 0.0));
    return {p + (-b - disc) * u, p + (-b + disc) * u};
}

std::vector<Vector2d> circleCircle(const Vector2d& c1, double r1, const Vector2d& c2, double r2) {
    const Vector2d d = c2 - c1;
    const double dist = d.norm();
    if (dist <= kEps) {
        return {};
    }
    const double a = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist);
    double h2 = r1 * r1 - a * a;
    if (h2 < -kEps * r1) {
        return {};
    }
    const double h = std::sqrt(std::max(h2, 0.0));
    const Vector2d mid = c1 + (a / dist) * d;
    const Vector2d n = leftNormal(d / dist);
    return {mid + h * n, mid - h * n};
}

} // namespace

std::vector<Vector2d> intersections(const OffsetPiece& a, const OffsetPiece& b) {
    const bool aLine = a.seg.kind == PathSegment::Kind::Line;
    const bool bLine = b.seg.kind == PathSegment::Kind::Line;
    if (aLine && bLine) {
        return lineLine(a.seg.end, a.direction, b.seg.end, b.direction);
    }
    if (aLine) {
        return lineCircle(a.seg.end, a.direction, b.seg.center, (b.seg.end - b.seg.center).norm());
    }
    if (bLine) {
        return lineCircle(b.seg.end, b.direction, a.seg.center, (a.seg.end - a.seg.center).norm());
    }
    return circleCircle(a.seg.center, (a.seg.end - a.seg.center).norm(), b.seg.center,
                        (b.seg.end - b.seg.center).norm());
}

bool contains(const OffsetPiece& piece, const Vector2d& p) {
    const PathSegment& s = piece.seg;
    if (s.kind == PathSegment::Kind::Line) {
        return (p - s.start).dot(piece.direction) >= -kEps && (p - s.end).dot(piece.direction) <= kEps;
    }
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    const double tolerance = kEps / (s.end - s.center).norm();
    double total = sweep(s.center, s.start, s.end, s.clockwise);
    if (piece.fullCircle && total <= tolerance) {
        total = kTwoPi;
    }
    const double at = sweep(s.center, s.start, p, s.clockwise);
    return at <= total + tolerance || at >= kTwoPi - tolerance;
}

void appendPiece(std::vector<PathSegment>& out, const OffsetPiece& piece, const Vector2d& to) {
    const bool empty = (to - piece.seg.start).norm() <= kEps;
    if (empty && !(piece.fullCircle && (to - piece.seg.end).norm() <= kEps)) {
        return;
    }
    PathSegment s = piece.seg;
    s.end = to;
    out.push_back(s);
}

void appendLine(std::vector<PathSegment>& out, const Vector2d& from, const Vector2d& to) {
    if ((to - from).norm() > kEps) {
        out.push_back(PathSegment::line(from, to));
    }
}

} // namespace m350::interp::ccgeom
