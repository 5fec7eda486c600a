#pragma once

#include "core/common/Alarm.h"

#include <cstdint>
#include <optional>
#include <string>

namespace m350::controller {

// After an E-stop, a RESET or an alarm stops a tool change, the controller no longer knows which
// tool the spindle holds: the change may have stopped before or after it put the old tool away,
// fetched the new one or recorded it (#1300 on the M350, the PMC's tool on a FANUC). It says so as
// the firmware does (msg 867: 目标刀号[T%d]与当前刀号[T%d]不同,请手动处理!) and refuses the next
// automatic change until the operator enters the tool the spindle holds
// (Controller::setSpindleToolNumber, the panel's 设置目标刀具号 prompt).
class ToolDoubt {
  public:
    struct Doubt {
        int target = 0;   // the tool the stopped change was fetching
        int recorded = 0; // the tool the controller had recorded in the spindle
    };

    // A change to `target` stopped with `recorded` on record; false when a doubt stood already.
    bool stoppedInChange(int target, int recorded);
    void confirmed() { doubt_.reset(); }
    const std::optional<Doubt>& doubt() const { return doubt_; }
    // What the controller says while in doubt, with its message id "tool_unsure" (T target, T recorded).
    Alarm notice() const;
    // Why a change is refused while in doubt ("tool_unsure_refused"), for the alarm at the T or M06.
    Message refusal() const;

  private:
    std::optional<Doubt> doubt_;
};

} // namespace m350::controller
