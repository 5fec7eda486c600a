#pragma once

#include "core/controller/RunSettings.h"
#include "core/controller/SensorWatch.h"
#include "core/controller/TraceWriter.h"
#include "core/gcode/Program.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace m350::params {
class ParameterTable;
struct PortAssignment;
}

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::controller {

// The inputs a macro reads, watched: a macro that keeps reading a sensor that never changes is
// waiting for it (SensorWatch). The real controller would hang there; the simulator says which
// input, and after RunSettings::sensorTimeout of virtual time stops with an alarm naming it. A
// wait for the operator's own keys is no fault: a run without an operator presses the extern
// START key when a macro waits for it, as the operator would.
class InputWatch {
public:
    // What the watch reads; all of it belongs to the Controller and outlives the watch.
    struct Context {
        const params::ParameterTable& parameters;
        const RunSettings& settings;
        machine::SimulatedMachine& machine;
        const gcode::Program& program; // the program running (a hook's while it runs)
        const std::unique_ptr<TraceWriter>& trace;
        std::function<std::optional<gcode::SourceLocation>()> location; // the line executing now
        std::function<std::string(int)> describeInput; // "IN11 (tool released)" in both languages (bilingual())
        std::function<void(const Message&)> post;                         // a line of the run's messages
    };

    explicit InputWatch(Context context) : context_(std::move(context)) {}

    // A macro read input `pin` at `level`; `unattended`: no operator, the controller presses START.
    // Throws the sensor-timeout alarm (macro::MacroError) once the wait has lasted too long.
    void read(int pin, int level, bool unattended);
    // The operator presses the extern START key (param 599's input) for a moment, as the
    // virtual-tool prompt asks; nothing when the key is not wired.
    void pressExternStart();
    // The wait under way as the panel shows it.
    std::optional<SensorWait> wait() const;
    void clear() { sensors_.clear(); }

private:
    void pressStartIfAwaited(const params::PortAssignment& key, int pin, int level, const gcode::SourceLocation& where);

    Context context_;
    SensorWatch sensors_;
};

} // namespace m350::controller
