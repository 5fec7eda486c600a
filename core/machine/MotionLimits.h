#pragma once

#include "core/machine/MachineTypes.h"

namespace m350::machine {

// How fast the machine may move, in machine units per second. Built from the parameters by the
// controller, so the machine itself knows no parameter numbers.
struct MotionLimits {
    double rapidSpeed = 10000.0 / 60.0;
    double maxSpeed = 12000.0 / 60.0;
    double feedAcceleration = 500.0;
    double rapidAcceleration = 2000.0;
    double spindleStartDelay = 0.0; // s
    double spindleStopDelay = 0.0;  // s
    double maxSpindleRpm = 24000.0;
};

// An input the spindle drives: active when the spindle has stopped (the M350's M300 signal).
struct SpindleStoppedSensor {
    int port = 0;        // 1-24, 0 when not wired
    int activeLevel = 0; // the level the input reads while the spindle is stopped
};

// A fixed tool setter (固定对刀仪): its switch closes when the tool tip comes down to its top inside
// its radius. The tip hangs the tool's length below the spindle, so the switch trips at machine Z =
// top + tool length: what the M350 records as the tool's Z offset (params 930-945).
struct ToolSetter {
    int port = 0;          // input 1-24, 0 when not fitted
    int activeLevel = 1;   // the level the input reads while pressed
    double x = 0.0;        // machine position of its center
    double y = 0.0;
    double radius = 5.0;   // mm
    double top = -100.0;   // machine Z the spindle nose would have at contact with a zero-length tool
};

// A home switch of the simulated world on one axis: pressed while the axis stands at `at` or
// beyond it on the switch's side (`side` -1 or +1, the homing direction). `at` is a machine
// coordinate; when homing gives the axes new coordinates the switch stays where it physically is.
struct HomeSwitch {
    int port = 0; // input 1-24, 0 when none
    int activeLevel = 0;
    double at = 0.0;
    double side = -1.0;

    bool pressedAt(double position) const { return (position - at) * side >= -1e-9; }
};

// The result of a G31 move.
struct ProbeResult {
    bool triggered = false;
    Axes position = Axes::Zero(); // machine coordinates where the signal came (or where the move ended)
};

} // namespace m350::machine
