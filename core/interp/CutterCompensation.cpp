#include "core/interp/CutterCompensation.h"

#include "core/interp/CutterCompensationGeometry.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace m350::interp {

using Eigen::Vector2d;
using namespace ccgeom;

namespace {

// Inside corners flatter than this may be joined with a straight line when the offsets do not meet:
// CAM output rounded to 1 um leaves tangent transitions a little off, and the overcut of such a join
// is at most r * angle^2 / 8. The value is LinuxCNC's TOLERANCE_CONCAVE_CORNER.
constexpr double kConcaveTolerance = 0.05;
// Consecutive programmed moves must meet; the interpreter hands over exact end points.
constexpr double kContinuity = 1e-6;

std::string mm(double v) {
    std::ostringstream s;
    const double rounded = std::round(v * 1000.0) / 1000.0;
    s << std::fixed << std::setprecision(3) << (rounded == 0.0 ? 0.0 : rounded);
    return s.str();
}

std::string at(const Vector2d& p) {
    return "X" + mm(p.x()) + " Y" + mm(p.y());
}

CompensationError error(Message words) {
    return CompensationError{std::move(words)};
}

// The intersection of an inside corner's offsets, if the tool reaches it without backing up on
// either piece.
std::optional<Vector2d> trimInside(const OffsetPiece& in, const OffsetPiece& out, const Vector2d& corner) {
    const std::vector<Vector2d> candidates = intersections(in, out);
    if (candidates.empty()) {
        return std::nullopt;
    }
    Vector2d nearest = candidates.front();
    for (const Vector2d& c : candidates) {
        if ((c - corner).norm() < (nearest - corner).norm()) {
            nearest = c;
        }
    }
    if (!contains(in, nearest) || !contains(out, nearest)) {
        return std::nullopt;
    }
    return nearest;
}

// The entry move, as LinuxCNC makes it: from where the tool stands to the radius beside the move's
// own end; the corner with the next move is then joined like any other, on the entry's offset line
// (an arc outside, a trim inside), so a diagonal entry leaves its mark on the profile as the
// LinuxCNC manual warns.
OffsetPiece entryPiece(const PathSegment& programmed, const Vector2d& toolStart, double signedRadius) {
    OffsetPiece piece;
    piece.seg = PathSegment::line(toolStart, offsetPoint(programmed, programmed.end, signedRadius));
    piece.direction = tangentAt(programmed, programmed.start); // the carrying line: parallel, through the end
    return piece;
}

} // namespace

double CutterCompensation::signedRadius(double radius) const {
    return side_ == CompensationSide::Right ? -radius : radius;
}

bool CutterCompensation::outsideCorner(const Vector2d& in, const Vector2d& out) const {
    const double turn = cross(in, out);
    if (std::abs(turn) <= kEps) {
        return in.dot(out) < 0.0; // a reversal goes around the end point
    }
    return side_ == CompensationSide::Left ? turn < 0.0 : turn > 0.0;
}

CutterCompensation::Result CutterCompensation::feed(const PathSegment& programmed, CompensationSide side,
                                                    double radius) {
    if (radius < 0.0) {
        radius = -radius;
        if (side != CompensationSide::Off) {
            side = side == CompensationSide::Left ? CompensationSide::Right : CompensationSide::Left;
        }
    }
    if (radius <= kEps) {
        side = CompensationSide::Off;
    }
    if (side_ == CompensationSide::Off) {
        if (side == CompensationSide::Off) {
            return std::vector<PathSegment>{programmed};
        }
        return enter(programmed, side, radius);
    }
    if (side == CompensationSide::Off) {
        return leave(programmed);
    }
    if (side != side_) {
        return error(message("compensation_switch_side"));
    }
    if (programmed.kind == PathSegment::Kind::Line && (programmed.end - programmed.start).norm() <= kEps) {
        return std::vector<PathSegment>{};
    }
    if (programmed.kind == PathSegment::Kind::Arc) {
        const double r = arcRadius(programmed);
        if (r <= kEps) {
            return error(message("compensation_arc_no_radius", {at(programmed.start)}));
        }
        if (offsetArcRadius(programmed, signedRadius(radius)) <= kEps) {
            return error(message("compensation_gouge_arc", {mm(r)}));
        }
    }
    return pending_ ? join(programmed, radius) : resume(programmed, radius);
}

CutterCompensation::Result CutterCompensation::enter(const PathSegment& programmed, CompensationSide side,
                                                     double radius) {
    if (programmed.kind != PathSegment::Kind::Line) {
        return error(message("compensation_start_arc"));
    }
    const double length = (programmed.end - programmed.start).norm();
    if (length <= radius) {
        return error(message("compensation_entry_short", {mm(length), mm(radius)}));
    }
    side_ = side;
    pending_ = Pending{programmed, programmed.start, radius, true};
    last_.reset();
    return std::vector<PathSegment>{};
}

CutterCompensation::Result CutterCompensation::leave(const PathSegment& programmed) {
    if (programmed.kind != PathSegment::Kind::Line) {
        return error(message("compensation_end_arc"));
    }
    std::vector<PathSegment> out = flush();
    appendLine(out, tool_, programmed.end);
    reset();
    return out;
}

CutterCompensation::Result CutterCompensation::resume(const PathSegment& programmed, double radius) {
    const Vector2d start = offsetPoint(programmed, programmed.start, signedRadius(radius));
    std::vector<PathSegment> out;
    const bool sameCorner = last_ && std::abs(lastRadius_ - radius) <= kEps &&
                            (last_->end - programmed.start).norm() <= kContinuity;
    if (sameCorner && (start - tool_).norm() > kEps &&
        outsideCorner(tangentAt(*last_, last_->end), tangentAt(programmed, programmed.start))) {
        out.push_back(PathSegment::arc(tool_, start, programmed.start, side_ == CompensationSide::Left));
    } else {
        appendLine(out, tool_, start);
    }
    pending_ = Pending{programmed, start, radius, false};
    last_.reset();
    return out;
}

CutterCompensation::Result CutterCompensation::join(const PathSegment& programmed, double radius) {
    const Pending& prev = *pending_;
    const Vector2d corner = prev.programmed.end;
    if ((programmed.start - corner).norm() > kContinuity) {
        return error(message("compensation_not_continuous", {at(programmed.start), at(corner)}));
    }
    const Vector2d nextStart = offsetPoint(programmed, programmed.start, signedRadius(radius));
    std::vector<PathSegment> out;
    Vector2d toolStart = nextStart;
    {
        const double sr = signedRadius(prev.radius);
        const OffsetPiece in = prev.entry ? entryPiece(prev.programmed, prev.toolStart, sr)
                                          : offsetPiece(prev.programmed, prev.toolStart, sr);
        const Vector2d tIn = tangentAt(prev.programmed, corner);
        const Vector2d tOut = tangentAt(programmed, programmed.start);
        const bool straightJoin =
            std::abs(prev.radius - radius) > kEps || (in.seg.end - nextStart).norm() <= kEps;
        if (straightJoin) {
            appendPiece(out, in, in.seg.end);
            appendLine(out, in.seg.end, nextStart);
        } else if (outsideCorner(tIn, tOut)) {
            appendPiece(out, in, in.seg.end);
            out.push_back(PathSegment::arc(in.seg.end, nextStart, corner, side_ == CompensationSide::Left));
        } else if (const auto trimmed =
                       trimInside(in, offsetPiece(programmed, nextStart, signedRadius(radius)), corner)) {
            appendPiece(out, in, *trimmed);
            toolStart = *trimmed;
        } else if (std::atan2(std::abs(cross(tIn, tOut)), tIn.dot(tOut)) < kConcaveTolerance) {
            appendPiece(out, in, in.seg.end);
            appendLine(out, in.seg.end, nextStart);
        } else {
            return error(message("compensation_gouge_corner", {mm(radius), at(corner)}));
        }
    }
    pending_ = Pending{programmed, toolStart, radius, false};
    return out;
}

std::vector<PathSegment> CutterCompensation::flush() {
    if (!pending_) {
        return {};
    }
    const Pending p = *pending_;
    const double sr = signedRadius(p.radius);
    const Vector2d end = offsetPoint(p.programmed, p.programmed.end, sr);
    std::vector<PathSegment> out;
    if (p.entry) {
        appendLine(out, p.toolStart, end);
    } else {
        appendPiece(out, offsetPiece(p.programmed, p.toolStart, sr), end);
    }
    tool_ = end;
    last_ = p.programmed;
    lastRadius_ = p.radius;
    pending_.reset();
    return out;
}

void CutterCompensation::reset() {
    side_ = CompensationSide::Off;
    pending_.reset();
    last_.reset();
    lastRadius_ = 0.0;
    tool_ = Vector2d::Zero();
}

} // namespace m350::interp
