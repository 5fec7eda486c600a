#include "core/machine/ArcGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace m350::machine {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Below the controller's 0.001 mm resolution, so only rounding noise counts as "same point".
constexpr double kSamePoint = 1e-6;
constexpr double kMinRadius = 1e-6;
// LinuxCNC's defaults: the end may miss the I/J/K circle by 0.002 mm and by 0.1 % of the radius.
constexpr double kRadiusAbsTolerance = 0.002;
constexpr double kRadiusRelTolerance = 0.001;
// An R rounded to three decimals may fall just short of a semicircle; accept it as one.
constexpr double kChordTolerance = 0.001;

struct PlaneAxes {
    int u, v, w;
};

PlaneAxes axesOf(machine::Plane plane) {
    switch (plane) {
    case machine::Plane::ZX: return {2, 0, 1};
    case machine::Plane::YZ: return {1, 2, 0};
    case machine::Plane::XY: break;
    }
    return {0, 1, 2};
}

std::string fixed3(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", value);
    return buffer;
}

// Signed angle from `from` to `to` turning the requested way, magnitude in (0, 2pi].
double sweepBetween(double from, double to, bool clockwise) {
    double d = std::fmod(clockwise ? from - to : to - from, kTwoPi);
    if (d <= 0.0) d += kTwoPi;
    return clockwise ? -d : d;
}

ArcError fail(Message words) { return ArcError{std::move(words)}; }

} // namespace

std::variant<Arc, ArcError> makeArc(const ArcSpec& spec) {
    if (!spec.start.allFinite() || !spec.end.allFinite()) return fail(message("arc_not_finite"));
    if (spec.turns < 0) return fail(message("arc_turns_negative"));

    const auto [u, v, w] = axesOf(spec.plane);
    const Eigen::Vector2d s(spec.start[u], spec.start[v]);
    const Eigen::Vector2d e(spec.end[u], spec.end[v]);
    const double chord = (e - s).norm();
    const bool closed = chord < kSamePoint;

    Eigen::Vector2d c;
    if (spec.radius) {
        const double r = *spec.radius;
        if (!std::isfinite(r) || std::abs(r) < kMinRadius) return fail(message("arc_r_zero"));
        if (closed) return fail(message("arc_r_full_circle"));
        const double half = chord / 2.0;
        if (half - std::abs(r) > kChordTolerance)
            return fail(message("arc_r_too_small", {fixed3(r), fixed3(half)}));
        const double h = std::sqrt(std::max(0.0, r * r - half * half));
        const Eigen::Vector2d d = (e - s) / chord;
        const Eigen::Vector2d left(-d.y(), d.x());
        // An arc of at most 180 deg has its center on the side it turns toward: left when counterclockwise.
        const bool centerLeft = spec.clockwise == (r < 0.0);
        c = (s + e) / 2.0 + (centerLeft ? h : -h) * left;
    } else if (spec.centerOffset) {
        const Eigen::Vector3d& ijk = *spec.centerOffset;
        if (!ijk.allFinite()) return fail(message("arc_ijk_not_finite"));
        c = s + Eigen::Vector2d(ijk[u], ijk[v]);
        const double r0 = (s - c).norm();
        const double r1 = (e - c).norm();
        if (std::min(r0, r1) < kMinRadius) return fail(message("arc_radius_zero"));
        const double err = std::abs(r0 - r1);
        if (err > kRadiusAbsTolerance || err > kRadiusRelTolerance * std::max(r0, r1))
            return fail(message("arc_end_off_circle", {fixed3(r0), fixed3(r1)}));
    } else {
        return fail(message("arc_needs_center"));
    }

    const double r0 = (s - c).norm();
    const double r1 = (e - c).norm();
    const double a0 = std::atan2(s.y() - c.y(), s.x() - c.x());
    const double a1 = std::atan2(e.y() - c.y(), e.x() - c.x());
    const double fullTurn = spec.clockwise ? -kTwoPi : kTwoPi;

    Arc arc;
    arc.plane = spec.plane;
    arc.start = spec.start;
    arc.end = spec.end;
    arc.center[u] = c.x();
    arc.center[v] = c.y();
    arc.center[w] = spec.start[w];
    arc.radius = (r0 + r1) / 2.0;
    arc.sweep = (closed ? fullTurn : sweepBetween(a0, a1, spec.clockwise)) + fullTurn * spec.turns;
    arc.helixLength = spec.end[w] - spec.start[w];
    const double rotary = (spec.end.tail<2>() - spec.start.tail<2>()).norm();
    const double planar = arc.radius * std::abs(arc.sweep);
    arc.length = std::sqrt(planar * planar + arc.helixLength * arc.helixLength + rotary * rotary);
    return arc;
}

machine::Axes Arc::pointAt(double s) const {
    if (!(s > 0.0)) return start;
    if (s >= length) return end;
    const double f = s / length;
    const int u = axesOf(plane).u;
    const int v = axesOf(plane).v;
    machine::Axes p = start + (end - start) * f;
    const double du0 = start[u] - center[u], dv0 = start[v] - center[v];
    const double r0 = std::hypot(du0, dv0);
    const double r1 = std::hypot(end[u] - center[u], end[v] - center[v]);
    // Blending the radius (a spiral within the end-point tolerance) makes both ends exact.
    const double r = r0 + (r1 - r0) * f;
    const double a = std::atan2(dv0, du0) + sweep * f;
    p[u] = center[u] + r * std::cos(a);
    p[v] = center[v] + r * std::sin(a);
    return p;
}

} // namespace m350::machine
