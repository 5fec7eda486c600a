#include "core/controller/OperationControl.h"

#include <cmath>
#include <cstdio>

namespace m350::controller {

std::optional<std::string> OperationControl::set(int variable, double value) {
    const int most = variable == 3 ? 3 : 7;
    if (value != std::floor(value) || value < 0 || value > most) {
        char text[192];
        std::snprintf(text, sizeof text, "#300%d = %.10g: it takes 0 to %d (%s)", variable, value, most,
                      variable == 3
                          ? "bit 0 no single block stop, bit 1 no wait for M, S, T completion"
                          : "bit 0 no feed hold, bit 1 no feed override, bit 2 no exact stop check");
        return std::string(text);
    }
    (variable == 3 ? singleBlock_ : feedHold_) = static_cast<int>(value);
    return std::nullopt;
}

} // namespace m350::controller
