#pragma once

#include "core/gcode/Diagnostic.h"

#include <cstdint>
#include <optional>
#include <string>

namespace m350::controller {

// A macro waiting for a sensor as the panel shows it (the same line reading an input unchanged
// while time passes): which input, which level it waits for, since when and where.
struct SensorWait {
    std::string input;   // "IN11 (tool released)"
    int awaitedLevel = 1;
    double seconds = 0.0; // waited so far
    std::string file;
    std::uint32_t line = 0;
};

// Notices a macro waiting for a sensor: the same program line reading the same input at the same
// level while virtual time passes (a WHILE loop around #[1520+k-1], an M301 wait). The controller
// reports the wait (status, trace) and raises an alarm once it has lasted the watchdog's time.
class SensorWatch {
public:
    struct Wait {
        int pin = 0;
        int level = 0;          // what the input keeps reading; the macro waits for the other level
        double since = 0.0;     // virtual time of the first read
        gcode::SourceLocation where;
    };
    enum class Verdict { Reading, WaitBegins, Waiting, TimedOut };

    // One read of input `pin` at `now` by the line at `where`.
    Verdict read(int pin, int level, double now, const gcode::SourceLocation& where, double timeout);
    void clear() { wait_.reset(); announced_ = false; }

    // The wait under way: a read repeated at least once with time passing.
    std::optional<Wait> current() const { return announced_ ? wait_ : std::nullopt; }

private:
    std::optional<Wait> wait_;
    bool announced_ = false;
};

} // namespace m350::controller
