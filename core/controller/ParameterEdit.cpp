// Parameters as the panel reads and writes them (teach buttons, the IO page's polarity).
#include "core/controller/Controller.h"
#include "core/params/ParameterLimits.h"

#include <cmath>

namespace m350::controller {

double Controller::parameter(int n) const {
    return params::ParameterTable::valid(n) ? config_.parameters.get(n) : 0.0;
}

bool Controller::setParameter(int n, double value) {
    if (!params::ParameterTable::valid(n) || !std::isfinite(value) || params::refusedParameterValue(n, value)) {
        return false;
    }
    config_.parameters.set(n, value);
    if (n == param::kCurrentTool && config_.dialect->id == gcode::DialectId::M350 && state_ != RunState::Running &&
        state_ != RunState::Hold) {
        toolDoubt_.confirmed(); // the Param page's 当前刀具号 entry: the operator says which tool it is
    }
    configureMachine(); // the setters, the spindle sensor and the speeds follow at once
    return true;
}

} // namespace m350::controller
