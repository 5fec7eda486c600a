#pragma once

#include "core/common/Message.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace m350::interp {

// Planar (G17, XY) cutter radius compensation with one segment of look-ahead.
//
// Conventions:
//   - Left (G41) puts the tool on the left of the direction of travel, seen from +Z; Right (G42) on
//     the right. A negative radius swaps the side (FANUC negative D, LinuxCNC negative diameter).
//     Radius 0 is no compensation: segments pass through unchanged, as with G40.
//   - Start-up (FANUC type A): the first move with a side, from Off, must be a straight line; the
//     tool goes straight from where it is to the offset point of the next segment's start, i.e. the
//     tool ends perpendicular to the start direction of the next segment. The move must be longer
//     than the radius (LinuxCNC's rule).
//   - Cancel (G40): the move that turns compensation off must be a straight line; the tool goes
//     straight from the offset end of the last segment (perpendicular to its end) to the programmed
//     point.
//   - Outside corners get a circular corner of the tool radius around the programmed corner point
//     (LinuxCNC's rule and FANUC's G39 corner arc, not FANUC's default linear corner extensions).
//   - Inside corners are trimmed at the intersection of the two offset segments; a trim that would
//     make the tool back up along either segment is a gouge and an error.
//   - Arcs keep their center; the offset radius is R + r for G41 CW / G42 CCW and R - r for G41 CCW /
//     G42 CW, and must stay positive.
//   - Changing the radius while compensating joins the two offsets with a straight line; changing the
//     side needs G40 first (LinuxCNC's rule).
struct PathSegment {
    enum class Kind { Line, Arc };
    Kind kind = Kind::Line;
    Eigen::Vector2d start = Eigen::Vector2d::Zero();
    Eigen::Vector2d end = Eigen::Vector2d::Zero();
    Eigen::Vector2d center = Eigen::Vector2d::Zero(); // arcs only
    bool clockwise = false;                           // arcs only; an arc with start == end is a full circle

    static PathSegment line(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
        return {Kind::Line, from, to, Eigen::Vector2d::Zero(), false};
    }
    static PathSegment arc(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                           const Eigen::Vector2d& center, bool clockwise) {
        return {Kind::Arc, from, to, center, clockwise};
    }
};

enum class CompensationSide { Off, Left /* G41 */, Right /* G42 */ };

struct CompensationError {
    Message message;
};

class CutterCompensation {
public:
    using Result = std::variant<std::vector<PathSegment>, CompensationError>;

    // Called for each programmed XY move in order (work coordinates). Returns the tool-center
    // segments that are now final: the previous segment up to its corner with this one, plus the
    // corner arc. On error nothing changes, so the caller may report it and reset().
    Result feed(const PathSegment& programmed, CompensationSide side, double radius);

    // Ends the pending segment at its own offset end (program end, G40 without motion, a non-XY
    // move). Compensation stays on: the next move starts from there.
    std::vector<PathSegment> flush();

    // Drops everything, compensation off (reset, alarm).
    void reset();

    CompensationSide side() const { return side_; }
    bool hasPending() const { return pending_.has_value(); }

private:
    struct Pending {
        PathSegment programmed;
        Eigen::Vector2d toolStart; // where the tool center starts this segment (already trimmed)
        double radius = 0.0;
        bool entry = false; // the start-up move: from the uncompensated start to beside its end
    };

    Result enter(const PathSegment& programmed, CompensationSide side, double radius);
    Result leave(const PathSegment& programmed);
    Result resume(const PathSegment& programmed, double radius);
    Result join(const PathSegment& programmed, double radius);
    double signedRadius(double radius) const;
    // Whether the path turns away from the tool side (or reverses) at a corner.
    bool outsideCorner(const Eigen::Vector2d& in, const Eigen::Vector2d& out) const;

    CompensationSide side_ = CompensationSide::Off;
    std::optional<Pending> pending_;
    // After flush() with compensation still on: the last programmed segment and where the tool is.
    std::optional<PathSegment> last_;
    double lastRadius_ = 0.0;
    Eigen::Vector2d tool_ = Eigen::Vector2d::Zero();
};

} // namespace m350::interp
