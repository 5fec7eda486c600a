#pragma once

#include "core/common/Message.h"
#include "core/controller/RunSettings.h"
#include "core/controller/TraceWriter.h"
#include "core/machine/MachineTypes.h"

#include <optional>

namespace m350::controller {

// The operator an unattended run (Controller::run(), m350-sim run) has not got: presses 暂停 at
// RunSettings::pauseAt and 急停 at estopAt (seconds after the start), and START after every hold,
// until holds in a row with the machine standing still show a program only an operator can end
// (`N1 M00` / `GOTO1`).
class UnattendedOperator {
public:
    // `runStartedAt`: the machine time the run started; `running`: whether it did (else nothing is pressed).
    UnattendedOperator(const RunSettings& settings, double runStartedAt, bool running);

    enum class Key { None, Pause, EStop };
    struct Press {
        Key key = Key::None;
        double at = 0.0; // machine time
    };
    // The next key to press and when (the earlier one first); None once both are pressed. Taken
    // off as it is returned.
    Press next();
    // What the messages say of a press made at `where`.
    Message pressed(const Press& press, const TraceSource& where) const;

    // The run holds with the machine at `at`: true when START is to be pressed, false once it has
    // held kMostIdleHolds times in a row without moving (the alarm is loopAlarm()).
    bool startAfterHold(const machine::Axes& at);
    Message loopWords(const TraceSource& where) const;

    // Far above any program's inspection stops in a loop, and reached in about a second (4 s of
    // virtual time).
    static constexpr int kMostIdleHolds = 20000;

private:
    double startedAt_;
    std::optional<double> pauseAt_;
    std::optional<double> estopAt_;
    std::optional<machine::Axes> heldAt_; // where the machine stood at the last hold
    int idleHolds_ = 0;                   // holds in a row with no move between them
};

} // namespace m350::controller
