#pragma once

namespace m350::machine {

// A fault a trainer puts on an input: a sensor stuck at one level, one whose every change arrives
// late (a slow cylinder, a dirty proximity switch), or one that chatters after each change (a
// bouncing contact). Faults act on what the controller reads, whatever drives the input.
struct InputFault {
    enum class Kind { Stuck, Delayed, Bouncing };
    Kind kind = Kind::Stuck;
    int level = 0;         // Stuck: the level read
    double seconds = 0.0;  // Delayed: the lateness; Bouncing: how long it chatters after a change
    double period = 0.002; // Bouncing: the length of one bounce

    static InputFault stuck(int level) { return {Kind::Stuck, level, 0.0, 0.0}; }
    static InputFault delayed(double seconds) { return {Kind::Delayed, 0, seconds, 0.0}; }
    static InputFault bouncing(double seconds, double period = 0.002) {
        return {Kind::Bouncing, 0, seconds, period};
    }
};

} // namespace m350::machine
