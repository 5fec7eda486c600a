#include "core/interp/PlaneRotation.h"

#include <cmath>
#include <numbers>

namespace m350::interp {

PlaneRotation::PlaneRotation(int u, int v, std::array<double, 2> centre, std::array<double, 2> toolAtStart,
                             double degrees)
    : u_(u), v_(v), centre_(centre), toolAtStart_(toolAtStart), cosine_(std::cos(degrees * std::numbers::pi / 180.0)),
      sine_(std::sin(degrees * std::numbers::pi / 180.0)) {}

machine::Axes PlaneRotation::turned(const machine::Axes& from, std::optional<double> du, std::optional<double> dv,
                                    bool incremental, const machine::Axes& workOffset) const {
    machine::Axes to = from;
    if (!du && !dv) {
        return to;
    }
    if (incremental) {
        const double su = du.value_or(0.0);
        const double sv = dv.value_or(0.0);
        to(u_) += cosine_ * su - sine_ * sv;
        to(v_) += sine_ * su + cosine_ * sv;
        return to;
    }
    // where `from` is in the program's own (turned) coordinates: turned back about the point the
    // program turns about so far
    const std::array<double, 2>& pivot = absoluteSeen_ ? centre_ : toolAtStart_;
    const double eu = from(u_) - workOffset(u_) - pivot[0];
    const double ev = from(v_) - workOffset(v_) - pivot[1];
    const double pu = du.value_or(pivot[0] + cosine_ * eu + sine_ * ev);
    const double pv = dv.value_or(pivot[1] - sine_ * eu + cosine_ * ev);
    const double qu = pu - centre_[0];
    const double qv = pv - centre_[1];
    to(u_) = centre_[0] + cosine_ * qu - sine_ * qv + workOffset(u_);
    to(v_) = centre_[1] + sine_ * qu + cosine_ * qv + workOffset(v_);
    return to;
}

void PlaneRotation::turn(Eigen::Vector3d& vector) const {
    const double a = vector(u_);
    const double b = vector(v_);
    vector(u_) = cosine_ * a - sine_ * b;
    vector(v_) = sine_ * a + cosine_ * b;
}

} // namespace m350::interp
