#pragma once

#include "core/common/Alarm.h"
#include "core/common/Message.h"
#include "core/macro/BlockSink.h"
#include "core/macro/Value.h"
#include "core/macro/VariableMap.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m350::macro {

// The variables that belong to the machine rather than to the macro interpreter: positions, work
// offsets, IO, homed flags, messages, modal state. The controller implements this; the executor
// never reaches the machine any other way.
class MachineAccess {
public:
    virtual ~MachineAccess() = default;

    virtual Value readSystem(const VariableInfo& info, int number) = 0;

    // `text` is the comment written after the value (`#1503 = 1(text)`), already formatted.
    // Returns a message when the machine refuses the write; the executor raises it as an alarm.
    virtual std::optional<Message> writeSystem(const VariableInfo& info, int number, double value,
                                               std::string_view text) = 0;

    // The dialect's built-in homing program (M350 `M98 P501 X<axis>`) when no library defines it:
    // homes `axis` (0 X .. 4 B) at once in virtual time. Returns the alarm when it cannot.
    struct HomingFailure {
        AlarmCode code;
        Message words;
    };
    virtual std::optional<HomingFailure> builtInHoming(int axis) {
        return HomingFailure{AlarmCode::NotHomed, message("homing_unavailable", {std::to_string(axis)})};
    }
    // A library's homing program (the M350's O501) is called for `axis`: the axis searches for its
    // switch from here on, with no trusted machine position until the program marks it homed.
    virtual void homingStarts(int axis) { (void)axis; }

    // A program writes parameter `parameter` (#(N+500) on the M350): the machine may refuse it (the
    // user level at the panel does not reach it); the executor raises the words as an alarm.
    virtual std::optional<Message> parameterWrite(int parameter, double value) {
        (void)parameter;
        (void)value;
        return std::nullopt;
    }

    // The machine's tool management sees each block's words before the executor takes its calls
    // out (tool life management: a group's T becomes its tool, H99/D99, the tool change, G10 L3 ..
    // G11 data). True when it took the whole block; throws MacroError to refuse it.
    virtual bool manageTools(EvaluatedBlock& block) {
        (void)block;
        return false;
    }
};

} // namespace m350::macro
