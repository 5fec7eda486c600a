#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace m350::machine {

inline constexpr int kAxisCount = 5;
inline constexpr std::array<char, kAxisCount> kAxisNames{'X', 'Y', 'Z', 'A', 'B'};
inline constexpr int kInputCount = 24;  // IN01-IN24
inline constexpr int kOutputCount = 21; // OUT01-OUT21

// Machine coordinates of X Y Z A B, in mm (or degrees for a rotary 4th/5th axis).
using Axes = Eigen::Matrix<double, kAxisCount, 1>;

enum class SpindleState : std::uint8_t { Stop, Forward, Reverse, Jog, Tap, Orient };
std::string_view spindleStateName(SpindleState state);

enum class Plane : std::uint8_t { XY, ZX, YZ }; // G17, G18, G19

struct Arc;

// A trace event as the machine reports it; the controller adds the source line that caused it.
struct MachineEvent {
    enum class Type : std::uint8_t { Rapid, Feed, Arc, Dwell, Io, Spindle, Coolant, Auxiliary } type = Type::Rapid;
    Axes from = Axes::Zero();
    Axes to = Axes::Zero();
    double feed = 0.0;
    double start = 0.0; // virtual seconds
    double end = 0.0;
    int port = 0;       // Io: output (>0) or input (<0) number; Auxiliary: the M code
    int level = 0;
    SpindleState spindle = SpindleState::Stop;
    double rpm = 0.0;
    const Arc* arc = nullptr; // an Arc event's path, valid only while observers are told
};

class MachineObserver {
public:
    virtual ~MachineObserver() = default;
    virtual void onMachineEvent(const MachineEvent& event) = 0;
    // A straight move (rapid or feed) from `from` to `to` that nothing of the observer's would
    // do anything with: the machine then makes no event of it. A query, which changes nothing.
    virtual bool ignoresMove(const Axes& /*from*/, const Axes& /*to*/) const { return false; }
};

} // namespace m350::machine
