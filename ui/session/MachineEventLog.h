#pragma once

namespace m350::controller {
class Controller;
}

namespace m350::ui {

class SessionLog;

// What the session enters in the 系统日志 of itself, beside the commands it runs: an alarm once,
// when the run falls into it (with its place), and every parameter change since the last look,
// whoever made it, with the level at the panel, the values and the program line that wrote it.
class MachineEventLog {
public:
    void noteAlarm(controller::Controller& controller, SessionLog& log);
    void noteParameterChanges(controller::Controller& controller, SessionLog& log);

private:
    bool alarmLogged_ = false; // the alarm in force is in the log
};

} // namespace m350::ui
