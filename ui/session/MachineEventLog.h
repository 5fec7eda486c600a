#pragma once

#include "core/common/Alarm.h"
#include "core/controller/ParameterWrites.h"

#include <functional>
#include <optional>
#include <vector>

namespace m350::ui {

class SessionLog;

// What the session enters in the 系统日志 of itself, beside the commands it runs: an alarm once,
// when the run falls into it (with its place), and every parameter change since the last look,
// whoever made it, with the level at the panel, the values and the program line that wrote it.
class MachineEventLog {
public:
    // `alarmed`: the run is in an alarm or an E-stop; `alarm` gives the one in force (asked only
    // when it is to be logged).
    void noteAlarm(bool alarmed, const std::function<std::optional<Alarm>()>& alarm, SessionLog& log);
    void noteParameterChanges(const std::vector<controller::ParameterWrites::Change>& changes, SessionLog& log);

private:
    bool alarmLogged_ = false; // the alarm in force is in the log
};

} // namespace m350::ui
