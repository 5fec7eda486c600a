#pragma once

#include "core/controller/ManualModes.h"
#include "core/controller/ManualMotionState.h"
#include "core/machine/SimulatedMachine.h"
#include "core/params/ParameterTable.h"

namespace m350::controller {

class RunView;

// The operator's manual control beside the run: the jog keys (连续 CONT, 寸动 STEP), the handwheel
// in MPG mode, the 试切 handwheel guide, the manual and spindle overrides, the spindle jog key and
// the IO page's output switches. Axis 0..4 = X Y Z A B. Moves start at the display time (or after a
// manual move still under way) and the run's advance() shows them; soft limits (param 155) bound
// every one. Motion is refused (false) while a program runs or holds, in alarm or E-stop.
class ManualControl {
public:
    static constexpr double kJogTravel = 10000.0; // mm a CONT jog runs without soft limits

    ManualControl(machine::SimulatedMachine& machine, const params::ParameterTable& parameters, RunView& run);

    void setJogMode(JogMode mode); // a held CONT key is released
    JogMode jogMode() const { return state_.mode; }
    void setJogStep(double distance); // mm (deg) per STEP press; ignored unless positive
    double jogStep() const { return state_.step; }
    void setJogHighSpeed(bool high); // 高速 params 40-44 / 低速 45-49, capped by 35-39
    // 手动倍率 SJR: 0 up to param 295 (150 % when it is 0); returns what applies.
    double setJogOverride(double percent);
    // CONT: moves until jogRelease() (to the soft limit, or kJogTravel); STEP: one jogStep();
    // MPG: nothing (false). direction +1 / -1.
    bool jogPress(int axis, int direction);
    // Key up: a CONT move brakes to rest at the manual stop acceleration (params 55-59).
    void jogRelease(int axis);
    // The handwheel: `detents` (signed) turned over the next `seconds` at x1, x10 or x100. With
    // the guide on and a program running it drives the guide; in MPG mode with no program running
    // it moves the axis detents * multiplier * param 172 (param 175 reverses) at up to the speed of
    // params 176-178, no faster than the wheel turns, ramping at params 181-185. Otherwise false.
    bool wheelTurn(int axis, int multiplier, int detents, double seconds);
    // Whether a manual move is still under way at the display time.
    bool jogging() const;

    // 试切 handwheel guide: while on and a program runs, the program's time advances only as the
    // wheel turns (see GuideOverride). Turning backwards holds or retraces the path already made
    // (the last SimulatedMachine::kHistoryMoves moves); turning forward again replays it, then new
    // blocks execute. A retrace undoes motion only: outputs, spindle and variables stay as the
    // blocks set them. Off: the run goes on at normal speed.
    void setHandwheelGuide(bool on);
    bool handwheelGuide() const { return state_.guide; }
    void setGuideReverse(GuideReverse mode) { state_.reverse = mode; }
    // How far the display time moves for `seconds` of the panel's time: as much, unless the guide
    // drives the run. advance(infinity) (run(), no operator) runs without the wheel.
    double displayStep(double seconds);

    // 主轴倍率 SRO, 50-150 % (clamped): the spindle speed shown follows it. Returns what applies.
    double setSpindleOverride(double percent);
    // The panel's spindle jog key (主轴点动): turns the spindle at param 85's speed, or stops it.
    // Refused (false) while a program runs.
    bool spindleJog(bool on);
    // The IO page's 输出开/输出关 for OUT01-OUT21 (level 0/1). Refused while a program runs or
    // holds and in E-stop.
    bool setOutputByOperator(int port, int level);

    // The settings and what is under way, for the panel's status.
    const ManualMotionState& state() const { return state_; }

private:
    bool manualAllowed() const;
    bool moveManually(int axis, double distance, double speed, double acceleration);
    static double reachWithin(double seconds, double speed, double acceleration);
    bool guideTurn(int multiplier, int detents, double seconds);

    machine::SimulatedMachine& machine_;
    const params::ParameterTable& parameters_;
    RunView& run_;
    ManualMotionState state_;
};

} // namespace m350::controller
