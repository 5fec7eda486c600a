#pragma once

#include "core/preview/PathSegment.h"

#include <cmath>
#include <numbers>

namespace m350::preview {

// An arc move in its plane's coordinates: u v in the plane, w along its normal (XY: x y z, ZX: z x
// y, YZ: y z x, so G2 is clockwise seen from +w in each).
struct PlanarArc {
    double cu = 0.0, cv = 0.0;         // centre
    double radius = 0.0;
    double startAngle = 0.0, sweep = 0.0; // radians; sweep < 0 clockwise (G2)
    double startW = 0.0, endW = 0.0;
    ArcPlane plane = ArcPlane::XY;

    static double u(const Point3& p, ArcPlane plane) { return plane == ArcPlane::XY ? p.x : plane == ArcPlane::ZX ? p.z : p.y; }
    static double v(const Point3& p, ArcPlane plane) { return plane == ArcPlane::XY ? p.y : plane == ArcPlane::ZX ? p.x : p.z; }
    static double w(const Point3& p, ArcPlane plane) { return plane == ArcPlane::XY ? p.z : plane == ArcPlane::ZX ? p.y : p.x; }

    PlanarArc(const Point3& start, const PathSegment& s, const ArcCentre& c) : cu(c.u), cv(c.v), plane(s.plane) {
        const double su = u(start, plane) - cu, sv = v(start, plane) - cv;
        const double eu = u(s.end, plane) - cu, ev = v(s.end, plane) - cv;
        radius = (std::hypot(su, sv) + std::hypot(eu, ev)) / 2.0;
        startAngle = std::atan2(sv, su);
        double end = std::atan2(ev, eu);
        sweep = end - startAngle;
        const bool clockwise = s.kind == SegmentKind::ArcCw;
        constexpr double full = 2.0 * std::numbers::pi;
        if (clockwise && sweep >= -1e-9) {
            sweep -= full; // start == end: a whole turn
        } else if (!clockwise && sweep <= 1e-9) {
            sweep += full;
        }
        startW = w(start, plane);
        endW = w(s.end, plane);
    }

    static Point3 point(double pu, double pv, double pw, ArcPlane plane) {
        switch (plane) {
        case ArcPlane::XY: return {float(pu), float(pv), float(pw)};
        case ArcPlane::ZX: return {float(pv), float(pw), float(pu)};
        case ArcPlane::YZ: return {float(pw), float(pu), float(pv)};
        }
        return {};
    }

    Point3 at(double fraction) const {
        const double a = startAngle + sweep * fraction;
        return point(cu + radius * std::cos(a), cv + radius * std::sin(a), startW + (endW - startW) * fraction, plane);
    }

    // The whole circle's square in the plane, from the start's to the end's height: never
    // smaller than the arc.
    Box box() const {
        Box b;
        b.add(point(cu - radius, cv - radius, startW, plane));
        b.add(point(cu + radius, cv + radius, endW, plane));
        return b;
    }

    // How many chords keep every point of the arc within `tolerance` of them (at least one).
    int chords(double tolerance) const {
        if (radius <= tolerance || tolerance <= 0.0) {
            return 1;
        }
        const double step = 2.0 * std::acos(1.0 - tolerance / radius);
        return std::max(1, int(std::ceil(std::abs(sweep) / step)));
    }
};

} // namespace m350::preview
