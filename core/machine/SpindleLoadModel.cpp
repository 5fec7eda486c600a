#include "core/machine/SpindleLoadModel.h"

#include <algorithm>
#include <cmath>

namespace m350::machine {

double SpindleLoadModel::percent(double rpm, double feed, double depth, double width) const {
    if (rpm <= 0.0) {
        return 0.0;
    }
    double removed = std::max(0.0, depth) * std::max(0.0, width) * std::max(0.0, feed) / 1000.0; // cm3/min
    return idle + perKrpm * rpm / 1000.0 + perCm3 * removed;
}

int SpindleLoadModel::signal(double percent) const {
    if (lambda <= 0.0) {
        return 0;
    }
    double l = std::round(percent / lambda * kSignalMax);
    return static_cast<int>(std::clamp(l, 0.0, static_cast<double>(kSignalMax)));
}

double loadPercent(int signal, double lambda) {
    return static_cast<double>(signal) / SpindleLoadModel::kSignalMax * lambda;
}

std::uint16_t loadRegister(int signal, double lambda) {
    // the ladder multiplies first (integer arithmetic), then divides: 14300 x L / 32767
    double scaled = std::floor(100.0 * lambda * signal / SpindleLoadModel::kSignalMax + 1e-9);
    return static_cast<std::uint16_t>(std::clamp(scaled, 0.0, 65535.0));
}

} // namespace m350::machine
