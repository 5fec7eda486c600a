#pragma once

#include "core/machine/ArcGeometry.h"
#include "core/machine/MachineTypes.h"
#include "core/machine/MotionLimits.h"

namespace m350::machine {

// The only way the interpreter reaches the machine. All positions are machine coordinates
// (mm, or degrees on rotary axes); feeds in mm/min; times in virtual seconds; ports 1-based.
class MachineInterface {
public:
    virtual ~MachineInterface() = default;

    // G0 to `target` at the rapid speed.
    virtual void rapid(const Axes& target) = 0;
    // G1 to `target` at `feed` mm/min.
    virtual void feed(const Axes& target, double feed) = 0;
    // G2/G3 along `arc` (machine coordinates, validated by makeArc) at `feed` mm/min.
    virtual void arc(const Arc& arc, double feed) = 0;
    // G31: moves toward `target` at `feed` until input `port` reads `level`, stopping there.
    virtual ProbeResult probe(const Axes& target, double feed, int port, int level) = 0;
    // G04: wait `seconds` of virtual time.
    virtual void dwell(double seconds) = 0;
    // Time spent preparing a block that does not move (macro statements, M codes).
    virtual void blockTime(double seconds) = 0;

    // An M code the machine's PMC answers (FANUC: the magazine's M81-M85, M10/M11 clamp): the block
    // waits until the PMC reports it done.
    virtual void auxiliary(int code) = 0;

    virtual void spindle(SpindleState state, double rpm) = 0;
    virtual void coolant(bool on) = 0;

    virtual void setOutput(int port, int level) = 0;
    virtual int output(int port) const = 0;
    // Logical input level (after polarity), as macros see it in #1520+k-1.
    virtual int input(int port) = 0;

    virtual const Axes& position() const = 0;
    virtual void setPosition(const Axes& position) = 0; // homing, or a macro writing #880..
    virtual double time() const = 0;
    virtual SpindleState spindleState() const = 0;
    virtual double spindleRpm() const = 0;
    virtual bool coolantOn() const = 0;
};

} // namespace m350::machine
