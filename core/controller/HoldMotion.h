#pragma once

#include "core/machine/MachineTypes.h"
#include "core/machine/SimulatedMachine.h"

#include <optional>
#include <utility>

namespace m350::params {
class ParameterTable;
}

namespace m350::controller {

// What a hold (暂停, M00, G04 P-1) does to the machine and START undoes: the move the hold cut
// short, the spindle stopped (param 84), Z lifted (param 91 by param 70), the axes pause.nc moved
// away from where the hold stopped them. RESET forgets it all.
class HoldMotion {
public:
    HoldMotion(machine::SimulatedMachine& machine, const params::ParameterTable& parameters);

    // 暂停 stopped the motion under way, leaving `rest`: the spindle stops and Z lifts as the
    // parameters say.
    void held(const machine::SimulatedMachine::Remainder& rest);
    // pause.nc ran after the hold stopped the axes at `stoppedAt`: START brings them back first
    // when it moved them.
    void pauseHookRan(const machine::Axes& stoppedAt);

    // What START finished of the cut-short move: whether it cut (a feed or an arc) and from when.
    struct Finished {
        bool cut = false;
        double from = 0.0;
    };
    // START: back to where the hold stopped the axes (Z up to the higher of the two, over, down),
    // Z down by the lift, the spindle as it turned, then the rest of the move cut short.
    Finished resume();
    // An E-stop: the move cut short is not taken again.
    void dropRemainder() { remainder_ = {}; }
    // RESET: nothing is taken again.
    void forget();

private:
    void returnAfterPauseHook();

    machine::SimulatedMachine& machine_;
    const params::ParameterTable& parameters_;
    machine::SimulatedMachine::Remainder remainder_; // what the hold cut short
    double liftedBy_ = 0.0;                          // Z lift of the hold (param 91, 70)
    std::optional<std::pair<machine::SpindleState, double>> spindleBeforeHold_;
    std::optional<machine::Axes> beforePauseHook_; // where the hold stopped the axes, if pause.nc moved them
};

} // namespace m350::controller
