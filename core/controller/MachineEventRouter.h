#pragma once

#include "core/config/MachineConfig.h"
#include "core/controller/RunSettings.h"
#include "core/controller/RunState.h"
#include "core/controller/TraceWriter.h"
#include "core/machine/MachineTypes.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace m350::machine {
class SimulatedMachine;
}

namespace m350::macro {
class Executor;
}

namespace m350::controller {

class MagazineDriver;
class StatusBoard;
class ToolBreakage;
class ToolLifeCounter;

// The machine's observer for the Controller: each machine event goes to the trace (an input an
// IoLink drives, with the line that switched its output), to RunSettings::observer, to the fixed
// setter's check (a rapid into it is a crash), to the magazine device, to tool life's cutting time
// and to the spindle load watch, whose anomaly stops the run. What the hardware suffers is thrown
// as a MacroError, so the alarm names the macro line that caused it.
class MachineEventRouter : public machine::MachineObserver {
public:
    // What the router feeds and reads; all of it belongs to the Controller and outlives it.
    struct Context {
        const config::MachineConfig& config;
        const RunSettings& settings;
        const machine::SimulatedMachine& machine;
        MagazineDriver& magazine;
        StatusBoard& status;
        ToolLifeCounter& toolLife;
        ToolBreakage& breakage;
        const RunState& state;
        const std::unique_ptr<macro::Executor>& executor; // made anew for each program
        std::function<void(double)> interruptMotion;     // stop the move under way at virtual time t
    };
    explicit MachineEventRouter(Context context);

    void onMachineEvent(const machine::MachineEvent& event) override;
    // Nothing listens to a straight move but a linear rack, which it passes wide of: no trace, no
    // observer, no cutting time counted, no spindle load or breakage to follow. Most moves of a program.
    bool ignoresMove(const machine::Axes& from, const machine::Axes& to) const override;

    // Input -> the program line that made it change (an output linked to it, a magazine sensor):
    // what the trace names for an input's event. The magazine driver writes its sensors' here.
    std::map<int, TraceSource>& inputSources() { return inputSource_; }
    // Where the move that ran into the hardware was going (the machine view marks it there), until
    // forgetCrash() at the next start.
    const std::optional<machine::Axes>& crashPlace() const { return crashPlace_; }
    void forgetCrash() { crashPlace_.reset(); }

private:
    void traceEvent(const machine::MachineEvent& event);
    void checkSetterRapid(const machine::MachineEvent& event);
    void feedMagazine(const machine::MachineEvent& event);
    void watchSpindleLoad(const machine::MachineEvent& event);
    bool alarmStands() const { return context_.state == RunState::Alarm || context_.state == RunState::EStop; }

    static constexpr double kSetterContact = 1e-3; // mm: a rapid that ends on the setter's top only touches it

    Context context_;
    std::map<int, TraceSource> inputSource_;
    std::optional<machine::Axes> crashPlace_;
};

} // namespace m350::controller
