#pragma once

namespace m350::controller {

// The handwheel guide's override (试切), as the M350 describes it: the wheel's speed sets a target
// override and the override steps toward it, by `change` (param 180) per step while the wheel
// turns and by `stop` (param 179) per step once it stands still, so the program ramps up and
// comes to rest smoothly. Values are signed fractions (1 = 100 %); negative runs the program's
// time backwards (a retrace). Reversing decelerates to zero at the stop step before turning back.
//
// One step every kStepSeconds of wall time. The firmware's interval for the guide is not
// documented (param 227's 500 us is the override step when leaving the guide); at 10 ms the ramp
// from rest to 100 % takes 1 s with the default param 180 (0.01) and the stop 0.2 s with param 179
// (0.05), which a 60 Hz display shows as a ramp.
class GuideOverride {
public:
    static constexpr double kStepSeconds = 0.010;
    struct Steps {
        double change = 0.01; // param 180
        double stop = 0.05;   // param 179
    };

    // The wheel turns in `direction` (+1 / -1) for the next `seconds` and asks for `target`
    // (signed; 0 with a reverse turn under Hold, which asks the program to stop).
    void turn(int direction, double target, double seconds);
    // `seconds` of wall time pass; returns the program time that passes with them (negative when
    // retracing).
    double advance(double seconds, const Steps& steps);
    // A stop outside the wheel (the guide switched off, the run ended): at rest at once.
    void reset() { *this = GuideOverride{}; }

    double value() const { return value_; }
    // +1 顺切, -1 逆切: the wheel's direction while it turns (and until the next step after its
    // last turn, so a panel that turns and advances frame by frame sees it), else the way the
    // program still moves; 0 at rest.
    int direction() const;

private:
    void step(bool turning, const Steps& steps);

    double value_ = 0.0;
    double target_ = 0.0;
    double turning_ = 0.0; // seconds the wheel still turns
    int wheelDirection_ = 0;
    double still_ = 0.0;   // seconds since the wheel last turned
    double phase_ = 0.0;   // seconds into the current step
};

} // namespace m350::controller
