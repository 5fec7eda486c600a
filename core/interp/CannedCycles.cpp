// The ModalInterpreter's canned drilling cycles, group 9: G73 G74 G81 G82 G83 G84 and G80. A cycle
// stays active until G80, a group-1 code (G0-G3) or the program end; each block in it that has an
// axis word of the plane, the drilling-axis word or R drills at the position it names, K (or L, as
// LinuxCNC writes it) times. The drilling data (Z R Q P) persists from block to block; in a cycle
// block R is the R level and P the dwell, never an arc radius or a program number.
#include "core/interp/ModalInterpreter.h"

#include "core/params/ParameterNumbers.h"

#include <array>
#include <cmath>

namespace m350::interp {

using macro::MacroError;
using macro::WordValue;

namespace {

// With parameter 224 at 0, G73/G83 back off by LinuxCNC's fixed amount (rs274's G83_RAPID_DELTA,
// 0.010 inch, whatever the unit), so that the differential tests compare the same moves. A FANUC
// takes it from parameters 5114 (G73) and 5115 (G83) instead.
constexpr double kDefaultPeckClearance = 0.254; // mm

// The two positioning axes and the drilling axis of a plane, as indexes into machine::Axes.
struct CycleAxes {
    std::array<int, 2> plane;
    int drill;
};

CycleAxes cycleAxes(int plane) {
    switch (plane) {
    case 18:
        return {{2, 0}, 1};
    case 19:
        return {{1, 2}, 0};
    default:
        return {{0, 1}, 2};
    }
}

char axisLetter(int axis) {
    return machine::kAxisNames[static_cast<std::size_t>(axis)];
}

} // namespace

std::uint32_t ModalInterpreter::cycleColumn(const Words& words) const {
    for (const WordValue& g : words.g) {
        if (std::abs(g.value - state_.group(9)) < 1e-6) {
            return g.column;
        }
    }
    return motionColumn(words);
}

// What a FANUC alarms on before the cycle moves: missing drilling data, no feed, a tap with the
// spindle the wrong way.
void ModalInterpreter::checkCycle(const Words& words, int code, char drillLetter) const {
    const std::string name = "G" + std::to_string(code);
    const std::uint32_t column = cycleColumn(words);
    drilling_.checkComplete(words, code, drillLetter, column);
    if (state_.feed <= 0) {
        const WordValue* f = words.find('F');
        throw MacroError::of(AlarmCode::InvalidWord, message("cycle_needs_f", {name}), f ? f->column : column);
    }
    machine::SpindleState spindle = machine_.spindleState();
    if (code == 84 && spindle != machine::SpindleState::Forward) {
        throw MacroError::of(AlarmCode::InvalidWord, message("g84_spindle"), column);
    }
    if (code == 74 && spindle != machine::SpindleState::Reverse) {
        throw MacroError::of(AlarmCode::InvalidWord, message("g74_spindle"), column);
    }
}

void ModalInterpreter::cannedCycle(const Words& words) {
    const int code = state_.group(9);
    const CycleAxes axes = cycleAxes(state_.group(2));
    const char drillLetter = axisLetter(axes.drill);
    if (compensating() || state_.group(7) != 40) {
        throw MacroError::of(AlarmCode::InvalidWord, message("cycle_compensation", {std::to_string(code)}),
                             cycleColumn(words));
    }
    for (char rotary : {'A', 'B'}) {
        if (const WordValue* w = words.find(rotary)) {
            invalidWord(*w, message("word_cycle_rotary", {wordText(*w), std::to_string(code)}));
        }
    }
    drilling_.remember(words, drillLetter);
    bool drills = words.find('R') || words.find(drillLetter) || words.find(axisLetter(axes.plane[0])) ||
                  words.find(axisLetter(axes.plane[1]));
    const int repeats = DrillingData::repeats(words);
    if (!drills || repeats == 0) {
        return; // K0 keeps the drilling data and drills nothing, as on a FANUC
    }
    checkCycle(words, code, drillLetter);
    drilling_.startAt(machine_.position()(axes.drill));
    const double clearance = parameters_.get(param::kDrillingRetraction);
    const DrillingData::Frame frame{axisUnit(axes.drill),         workOffset()(axes.drill),
                                    state_.incremental(),         state_.group(10) == 99,
                                    clearance > 0 ? clearance : kDefaultPeckClearance, dialect_.dwellPScale};
    runCycle(drilling_.resolve(words, code, axes.drill, frame, cycleColumn(words)), cycleHoles(words, repeats), words);
}

// Where the block drills: once at the position it names, or under G91 `repeats` steps apart.
std::vector<machine::Axes> ModalInterpreter::cycleHoles(const Words& words, int repeats) const {
    const CycleAxes axes = cycleAxes(state_.group(2));
    const machine::Axes offset = workOffset();
    std::vector<machine::Axes> holes;
    machine::Axes hole = machine_.position();
    for (int i = 0; i < repeats; ++i) {
        if (state_.rotating()) { // the holes of a pattern G68 turns (CoordinateRotation.cpp)
            hole = turnedInPlane(hole, words);
            holes.push_back(hole);
            continue;
        }
        for (int axis : axes.plane) {
            if (const WordValue* w = words.find(axisLetter(axis))) {
                double value = w->value * axisUnit(axis);
                hole(axis) = state_.incremental() ? hole(axis) + value : value + offset(axis);
            }
        }
        holes.push_back(hole);
    }
    return holes;
}

void ModalInterpreter::runCycle(const DrillingCycle& cycle, const std::vector<machine::Axes>& holes,
                                const Words& words) {
    const machine::Axes from = machine_.position();
    // The whole block is checked against the soft limits before the first move, as for any block.
    cycle.plan(from, holes, [&](const CycleStep& step) {
        if (step.kind == CycleStep::Kind::Rapid || step.kind == CycleStep::Kind::Feed) {
            checkSoftLimits(step.target, words);
        }
    });
    cycle.plan(from, holes, [&](const CycleStep& step) {
        switch (step.kind) {
        case CycleStep::Kind::Rapid:
            machine_.rapid(step.target);
            break;
        case CycleStep::Kind::Feed:
            machine_.feed(step.target, motionFeedRate(words));
            break;
        case CycleStep::Kind::Dwell:
            machine_.dwell(step.seconds);
            break;
        case CycleStep::Kind::Spindle:
            machine_.spindle(step.spindle, state_.spindleSpeed);
            break;
        }
    });
}

} // namespace m350::interp
