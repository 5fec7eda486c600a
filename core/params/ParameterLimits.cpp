#include "core/params/ParameterLimits.h"

#include "core/common/Numeric.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <cmath>

namespace m350::params {

std::optional<Message> refusedParameterValue(int number, double value) {
    if (number == param::kMagazineCapacity && !(value >= 0 && value <= kMostPockets && value == std::floor(value))) {
        return message("param_capacity_range", {std::to_string(kMostPockets)});
    }
    return std::nullopt;
}

int magazineCapacity(const ParameterTable& parameters) {
    return std::clamp(saturatingInt(parameters.get(param::kMagazineCapacity)), 0, kMostPockets);
}

} // namespace m350::params
