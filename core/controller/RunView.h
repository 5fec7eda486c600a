#pragma once

#include "core/common/Alarm.h"
#include "core/controller/RunState.h"

#include <string>
#include <vector>

namespace m350::controller {

// What the Controller's parts beside the run (manual control, homing) read of it, and where they
// report: an alarm they raise stops the run as any other does, and --max-sim-time bounds their
// motion as it bounds a program's.
class RunView {
public:
    virtual RunState runState() const = 0;
    // The panel's time: manual moves start there, the handwheel guide moves it.
    virtual double displayTime() const = 0;
    // The machine time the run started at (the guide retraces no further back).
    virtual double runStartedAt() const = 0;
    virtual void raiseAlarm(const Alarm& alarm) = 0;
    // #1515-#1519: the soft limits guard a manual move only on a homed axis, as a program's.
    virtual bool axisHomed(int axis) const = 0;
    // True once what started at machine time `since` ran longer than --max-sim-time; the motion
    // under way is then stopped where the limit found it.
    virtual bool passedTimeLimit(double since) = 0;
    // The runaway guard's numbers, as its messages say them: the limit in simulated seconds, and
    // when `since` is not 0 the machine's clock from `since` to now.
    virtual std::vector<std::string> timeLimitNumbers(double since) const = 0;

protected:
    ~RunView() = default;
};

} // namespace m350::controller
