#include "core/params/ParameterLimits.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>

namespace m350::params {

std::optional<std::string> refusedParameterValue(int number, double value) {
    if (number == param::kMagazineCapacity && !(value >= 0 && value <= kMostPockets && value == std::floor(value))) {
        return "parameter 801 (magazine capacity) must be a whole number from 0 to " + std::to_string(kMostPockets) +
               " here (the M350 holds up to 20)";
    }
    return std::nullopt;
}

int magazineCapacity(const ParameterTable& parameters) {
    return std::clamp(saturatingInt(parameters.get(param::kMagazineCapacity)), 0, kMostPockets);
}

} // namespace m350::params
