#include "core/controller/ToolDoubt.h"

namespace m350::controller {

bool ToolDoubt::stoppedInChange(int target, int recorded) {
    if (doubt_) {
        return false; // the E-stop, then its RESET: one stop, one doubt
    }
    doubt_ = Doubt{target, recorded};
    return true;
}

Alarm ToolDoubt::notice() const {
    Alarm out;
    out.code = AlarmCode::OperatorReset;
    if (!doubt_) {
        return out;
    }
    const std::string target = std::to_string(doubt_->target);
    const std::string recorded = std::to_string(doubt_->recorded);
    out.message = "the change to T" + target + " was stopped: the target tool [T" + target +
                  "] may differ from the current one [T" + recorded +
                  "]; handle it by hand and enter the tool the spindle holds";
    out.messageId = "tool_unsure";
    out.messageArguments = {target, recorded};
    return out;
}

Message ToolDoubt::refusal() const {
    return message("tool_unsure_refused", {std::to_string(doubt_ ? doubt_->target : 0)});
}

} // namespace m350::controller
