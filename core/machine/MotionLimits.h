#pragma once

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

} // namespace m350::machine
