#pragma once

#include "core/machine/MachineTypes.h"

#include <functional>
#include <vector>

namespace m350::interp {

// One step of a canned drilling cycle (G73 G74 G81-G84); positions in machine coordinates.
struct CycleStep {
    enum class Kind : std::uint8_t { Rapid, Feed, Dwell, Spindle };
    Kind kind = Kind::Rapid;
    machine::Axes target = machine::Axes::Zero();                // Rapid, Feed
    double seconds = 0.0;                                        // Dwell
    machine::SpindleState spindle = machine::SpindleState::Stop; // Spindle
};

// One cycle block resolved to machine coordinates. Levels are positions on the drilling axis (the
// axis normal to the plane: Z under G17, Y under G18, X under G19), drilling toward minus.
struct DrillingCycle {
    int code = 81;              // 73 74 81 82 83 84
    int drillAxis = 2;          // index into machine::Axes
    double initialLevel = 0.0;  // where the cycle began (G98 returns here)
    double r = 0.0;             // R level: rapid down to here, drilling starts here
    double bottom = 0.0;        // the Z word: hole bottom
    bool returnToR = false;     // G99
    double peck = 0.0;          // Q, mm (G73, G83)
    double peckClearance = 0.0; // d, mm: G73's back-off, G83's stop above the last depth
    double dwell = 0.0;         // seconds at the bottom (G82, G74, G84)

    using Emit = std::function<void(const CycleStep&)>;

    // Hands `emit` the steps that drill at each of `holes` (their drilling-axis coordinate is not
    // used), the tool standing at `from` before the first. Steps are produced one at a time rather
    // than collected: a small Q over a deep hole makes very many of them.
    void plan(const machine::Axes& from, const std::vector<machine::Axes>& holes, const Emit& emit) const;

  private:
    void drill(const machine::Axes& atR, double clear, const Emit& emit) const;
};

} // namespace m350::interp
