#include "core/config/RackForks.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>

namespace m350::config {

std::vector<Eigen::Vector3d> rackForks(const MagazineConfig& m, const params::ParameterTable& p) {
    std::vector<Eigen::Vector3d> forks;
    if (!m.forks.empty()) {
        for (const auto& at : m.forks) {
            forks.emplace_back(at[0], m.onGantry ? 0.0 : at[1], at[2]);
        }
        return forks;
    }
    const int capacity = std::clamp(saturatingInt(p.get(param::kMagazineCapacity)), 0, 20);
    for (int k = 1; k <= capacity; ++k) {
        const double y = m.onGantry ? 0.0 : p.get(param::kPocketY + k - 1);
        Eigen::Vector3d at(p.get(param::kPocketX + k - 1), y, p.get(param::kPocketZ + k - 1));
        if (at.isZero() || (m.onGantry && at.x() == 0.0 && at.z() == 0.0)) {
            break; // no position set: the rack ends here, whatever param 801 says
        }
        forks.push_back(at);
    }
    return forks;
}

} // namespace m350::config
