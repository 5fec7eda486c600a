#include "core/controller/OperationControl.h"

#include <cmath>
#include <cstdio>

namespace m350::controller {

std::optional<Message> OperationControl::set(int variable, double value) {
    const int most = variable == 3 ? 3 : 7;
    if (value != std::floor(value) || value < 0 || value > most) {
        char text[32];
        std::snprintf(text, sizeof text, "%.10g", value);
        return message(variable == 3 ? "operation_control_3003" : "operation_control_3004", {text});
    }
    (variable == 3 ? singleBlock_ : feedHold_) = static_cast<int>(value);
    return std::nullopt;
}

} // namespace m350::controller
