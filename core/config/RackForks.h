#pragma once

#include "core/config/MagazineConfig.h"
#include "core/params/ParameterTable.h"

#include <Eigen/Core>

#include <vector>

namespace m350::config {

// Where a linear rack's forks stand, pocket 1 first: [magazine] forks when the folder gives them,
// else params 830+/850+/870+ for param 801 pockets (at most 20), ending at the first pocket with no
// position. On the gantry a fork's Y is 0 (it stands beside the spindle; the slide moves it).
std::vector<Eigen::Vector3d> rackForks(const MagazineConfig& magazine, const params::ParameterTable& parameters);

} // namespace m350::config
