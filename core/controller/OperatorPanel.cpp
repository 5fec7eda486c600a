#include "core/controller/OperatorPanel.h"

namespace m350::controller {

std::optional<SensorWait> OperatorPanel::sensorWait() const {
    if (!context_.running()) {
        return std::nullopt;
    }
    return inputWatch_.wait();
}

} // namespace m350::controller
