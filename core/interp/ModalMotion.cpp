// The ModalInterpreter's positioning: targets in machine coordinates, the coordinate-setting codes
// (G92, G52, G10), reference returns (G28, G30), one-shot machine coordinates (G53), soft limits
// and the motion itself (G0, G1, G2, G3; the canned cycles are in CannedCycles.cpp).
#include "core/interp/ModalInterpreter.h"

#include "core/common/Numeric.h"
#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"
#include "core/machine/ArcGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace m350::interp {

using macro::MacroError;
using macro::WordValue;

namespace {

constexpr std::array<char, 3> kCenterLetters{'I', 'J', 'K'};

std::string millimetres(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", v);
    return buffer;
}

} // namespace

machine::Axes ModalInterpreter::plainTarget(const Words& words, bool machineCoordinates) const {
    machine::Axes target = basePosition();
    const bool incremental = state_.incremental();
    const bool inches = state_.inches(); // else every axis unit is 1
    const machine::Axes* offset = machineCoordinates || incremental ? nullptr : &workOffset();
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const auto* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)]);
        if (!w) {
            continue;
        }
        double v = inches ? w->value * axisUnit(axis) : w->value;
        if (machineCoordinates) {
            target(axis) = v;
        } else if (incremental) {
            target(axis) += v;
        } else {
            target(axis) = v + (*offset)(axis);
        }
    }
    return target;
}

double ModalInterpreter::axisUnit(int axis) const {
    if (!state_.inches()) {
        return 1.0;
    }
    bool rotary = axis >= 3 && parameters_.get(param::kFourthAxisType + axis - 3) != 0.0;
    return rotary ? 1.0 : 25.4;
}

// G95 (FANUC): F is mm per spindle revolution, so the feed follows the spindle's speed. The M350
// ignores G94/G95 (its manual: use M29 for tapping), so its F stays mm/min.
double ModalInterpreter::feedRate(std::uint32_t column) const {
    if (state_.group(5) != 95 || dialect_.id == gcode::DialectId::M350) {
        return state_.feed;
    }
    double rpm = machine_.spindleRpm();
    if (rpm <= 0.0) {
        throw MacroError::of(AlarmCode::InvalidWord, message("g95_spindle_stopped"), column);
    }
    return state_.feed * rpm;
}

std::uint32_t ModalInterpreter::motionColumn(const Words& words) const {
    if (!words.g.empty()) {
        return words.g.front().column;
    }
    for (char axis : machine::kAxisNames) {
        if (const WordValue* w = words.find(axis)) {
            return w->column;
        }
    }
    return 0;
}

// Param 155 switches the limits of params 161-170 on; a move that would cross one is refused before
// the machine moves, as the controller checks the whole block first. They guard only a homed axis
// (#1515-#1519): one not homed, or whose homing has begun, has no trusted machine position, and the
// homing search (a factory O501's long G31 toward the switch) must be free to run past them.
void ModalInterpreter::checkAgainstSoftLimits(const machine::Axes& target, const Words& words) const {
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        if (homed_ != nullptr && (*homed_)[static_cast<std::size_t>(axis)] == 0) {
            continue;
        }
        double low = parameters_.get(param::kSoftLimitNegativeX + axis);
        double high = parameters_.get(param::kSoftLimitPositiveX + axis);
        char name = machine::kAxisNames[static_cast<std::size_t>(axis)];
        if (target(axis) > high + 1e-9 || target(axis) < low - 1e-9) {
            bool positive = target(axis) > high;
            int number = (positive ? param::kSoftLimitPositiveX : param::kSoftLimitNegativeX) + axis;
            throw MacroError::of(AlarmCode::SoftLimit,
                                 message("soft_limit", {std::string(1, name), positive ? "+" : "-", millimetres(target(axis)),
                                                        millimetres(positive ? high : low), std::to_string(number)}),
                                 motionColumn(words));
        }
    }
}

void ModalInterpreter::moveTo(const machine::Axes& target, const Words& words) {
    if (compensating() || state_.group(7) != 40) {
        const PlaneAxes plane = compensating() ? compensationPlane_ : planeAxes(state_.group(2));
        machine::Axes base = basePosition();
        bool samePlace = std::abs(target(plane.u) - base(plane.u)) < 1e-12 &&
                         std::abs(target(plane.v) - base(plane.v)) < 1e-12;
        if (!samePlace || state_.group(7) == 40) {
            compensatedMove(target, words);
            return;
        }
        // A plunge or lift under compensation (along the plane's normal): the tool path so far is
        // final, then that axis moves alone where the tool stands.
        flushCompensation();
        programmed_ = target;
        machine::Axes tool = target;
        tool(plane.u) = machine_.position()(plane.u);
        tool(plane.v) = machine_.position()(plane.v);
        checkSoftLimits(tool, words);
        state_.group(1) == 0 ? machine_.rapid(tool) : machine_.feed(tool, motionFeedRate(words));
        return;
    }
    checkSoftLimits(target, words);
    switch (state_.group(1)) {
    case 0: machine_.rapid(target); return;
    case 1:
        if (state_.feed <= 0) {
            throw MacroError::of(AlarmCode::InvalidWord, message("g01_no_feed"), motionColumn(words));
        }
        machine_.feed(target, motionFeedRate(words));
        return;
    default: break;
    }
    if (state_.feed <= 0) {
        throw MacroError::of(AlarmCode::InvalidWord, message("arc_no_feed"), motionColumn(words));
    }
    machine::ArcSpec spec;
    spec.start = machine_.position();
    spec.end = target;
    spec.plane = state_.group(2) == 18 ? machine::Plane::ZX : state_.group(2) == 19 ? machine::Plane::YZ
                                                                                      : machine::Plane::XY;
    spec.clockwise = state_.group(1) == 2;
    double unit = state_.inches() ? 25.4 : 1.0;
    if (const WordValue* r = words.find('R')) {
        spec.radius = r->value * unit;
    } else {
        Eigen::Vector3d center = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < kCenterLetters.size(); ++k) {
            if (const WordValue* w = words.find(kCenterLetters[k])) {
                center(static_cast<Eigen::Index>(k)) = w->value * unit;
            }
        }
        if (state_.rotating()) {
            state_.rotation.turn(center);
        }
        spec.centerOffset = center;
    }
    auto arc = machine::makeArc(spec);
    if (auto* error = std::get_if<machine::ArcError>(&arc)) {
        throw MacroError::of(AlarmCode::InvalidWord, error->message, motionColumn(words));
    }
    machine_.arc(std::get<machine::Arc>(arc), motionFeedRate(words));
}

void ModalInterpreter::moveOtherwise(const Words& words) {
    if (words.hasG(92) || words.hasG(52)) {
        setCoordinateSystem(words);
        return;
    }
    if (words.hasG(10)) {
        setOffsets(words);
        return;
    }
    if (words.hasG(4)) {
        return; // in a G04 block, X is the dwell time (FANUC), not a move
    }
    if (words.hasG(68)) {
        return; // its axis words are the centre of rotation (applyGCodes), R the angle
    }
    if (dialect_.lookAheadCodes && isLookAheadBlock(words)) {
        return; // its P and Q are the mode, not a canned cycle's data
    }
    if (state_.group(9) != 80 && !words.hasG(53) && !words.hasG(28) && !words.hasG(30) && !words.hasG(31)) {
        cannedCycle(words);
        return;
    }
    if (!words.hasAxis()) {
        return;
    }
    if (words.hasG(53)) {
        // One-shot machine coordinates; with F (the M350's `G53 Z#1306 F#1312`) a feed move
        machine::Axes target = targetFor(words, true);
        checkSoftLimits(target, words);
        if (words.find('F')) {
            machine_.feed(target, feedRate(words.find('F')->column));
        } else {
            machine_.rapid(target);
        }
        return;
    }
    if (words.hasG(28)) {
        goToReference(words, 1);
        return;
    }
    if (words.hasG(31)) {
        probeMove(words);
        return;
    }
    if (words.hasG(30)) {
        const WordValue* p = words.find('P');
        goToReference(words, p ? roundToInt(p->value) : 2);
        return;
    }
    moveTo(targetFor(words, false), words);
}

// G31 skip: the M350 names the input and level (`G31 Z-50 F100 P12 L1`); FANUC's skip signal is
// wired to the fixed setter's input (params 575-577). The move stops where the signal comes; a
// move that ends without it is an alarm.
void ModalInterpreter::probeMove(const Words& words) {
    const WordValue& g31 = *std::find_if(words.g.begin(), words.g.end(), [](const WordValue& w) {
        return std::abs(w.value - 31) < 1e-9;
    });
    int port = 0;
    int level = 1;
    if (dialect_.id == gcode::DialectId::M350) {
        const WordValue* p = words.find('P');
        port = p ? roundToInt(p->value) : 0;
        const WordValue* l = words.find('L');
        level = l ? (l->value != 0.0 ? 1 : 0) : 1;
    } else if (auto setter = params::wiredInput(parameters_, param::kFixedSetterInput)) {
        port = setter->pin;
        level = setter->activeLevel;
    }
    if (port < 1 || port > machine::kInputCount) {
        invalidWord(g31, message(dialect_.id == gcode::DialectId::M350 ? "word_g31_needs_port" : "word_g31_no_skip",
                             {wordText(g31)}));
    }
    if (state_.feed <= 0) {
        invalidWord(g31, message("word_g31_no_feed", {wordText(g31)}));
    }
    machine::Axes target = targetFor(words, false);
    checkSoftLimits(target, words);
    probe_ = Probe{};
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        if (words.find(machine::kAxisNames[static_cast<std::size_t>(axis)])) {
            probe_.axes |= 1u << axis;
        }
    }
    machine::ProbeResult result = machine_.probe(target, feedRate(g31.column), port, level);
    probe_.triggered = result.triggered;
    probe_.position = result.position;
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        probe_.status[static_cast<std::size_t>(axis)] = (probe_.axes & (1u << axis)) && result.triggered ? 2.0 : 0.0;
    }
    // A FANUC G31 that never sees the signal ends at its end point, which #5061-#5065 then hold: the
    // TS27R macros move beside the stylus by G31 so that a touch on the way stops them. The M350
    // alarms, as its probing hooks expect.
    if (!result.triggered && dialect_.id == gcode::DialectId::M350) {
        std::string where;
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            if (probe_.axes & (1u << axis)) {
                where += std::string(1, machine::kAxisNames[static_cast<std::size_t>(axis)]) +
                         millimetres(target(axis) - workOffset()(axis));
            }
        }
        throw MacroError::of(AlarmCode::SkipNotTriggered,
                             message("skip_not_triggered", {std::string(port < 10 ? "0" : "") + std::to_string(port),
                                                            std::to_string(level), where}),
                             g31.column);
    }
}

// G28 / G30: through the intermediate point given by the axis words, then those axes alone to the
// reference point. The M350's G28 goes to the position after homing (params 122-126).
void ModalInterpreter::goToReference(const Words& words, int point) {
    machine::Axes intermediate = targetFor(words, false);
    checkSoftLimits(intermediate, words);
    machine_.rapid(intermediate);
    machine::Axes reference = machine::Axes::Zero();
    if (point == 1 && dialect_.id == gcode::DialectId::M350) {
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            reference(axis) = parameters_.get(param::kHomePositionX + axis);
        }
    } else if (auto it = referencePoints_.find(point); it != referencePoints_.end()) {
        reference = it->second;
    } else if (point != 1) {
        throw MacroError::of(AlarmCode::InvalidWord, message("g30_point_unset", {std::to_string(point)}),
                             motionColumn(words));
    }
    machine::Axes target = machine_.position();
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        if (words.find(machine::kAxisNames[static_cast<std::size_t>(axis)])) {
            target(axis) = reference(axis);
        }
    }
    machine_.rapid(target);
}

// G92 gives the current position new work coordinates; G52 shifts a local system (G52 X0 Y0 ends it).
void ModalInterpreter::setCoordinateSystem(const Words& words) {
    bool local = words.hasG(52);
    machine::Axes position = machine_.position();
    machine::Axes offset = workOffset();
    int slot = local ? WorkOffsets::kG52 : dialect_.id == gcode::DialectId::M350 ? activeSlot() : WorkOffsets::kG92;
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        if (const WordValue* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)])) {
            double value = w->value * axisUnit(axis);
            if (local) {
                offsets_.set(slot, axis, value);
            } else {
                offsets_.set(slot, axis, offsets_.get(slot, axis) + (position(axis) - offset(axis)) - value);
            }
        }
    }
}

// FANUC G10: L2 P0-6 writes a work offset (P0 the external one), L20 Pn the offset of the additional
// system G54.1 Pn (both: G91 adds). L1 and L10-L13 write tool offsets: FANUC's P R forms and
// LinuxCNC's P<tool> forms with axis words (ToolTableCodes.cpp); L0 reloads the tool table.
void ModalInterpreter::setOffsets(const Words& words) {
    const WordValue& g10 = *std::find_if(words.g.begin(), words.g.end(), [](const WordValue& w) {
        return std::abs(w.value - 10) < 1e-9;
    });
    if (dialect_.id == gcode::DialectId::M350) {
        invalidWord(g10, message("word_m350_no_g10", {wordText(g10)}));
    }
    const WordValue* l = words.find('L');
    const WordValue* p = words.find('P');
    if (l && !p && std::abs(l->value) < 1e-9) {
        reloadToolTable(g10); // LinuxCNC's G10 L0 has no P
        return;
    }
    if (!l || !p) {
        invalidWord(g10, message("word_g10_needs_l_p", {wordText(g10)}));
    }
    int kind = roundToInt(l->value);
    int number = roundToInt(p->value);
    if (kind == 0 && std::abs(l->value) < 1e-9) {
        reloadToolTable(g10);
        return;
    }
    if (kind == 1 || (kind >= 10 && kind <= 13)) {
        setToolOffsets(words, g10, kind);
        return;
    }
    const int systems = features_.additionalSystems;
    if (kind == 20 && (number < 1 || number > systems)) {
        invalidWord(g10, systems > 0 ? message("word_g10_l20_range", {wordText(g10), std::to_string(systems)})
                                 : message("word_g10_l20_none", {wordText(g10)}));
    }
    if (kind != 20 && (kind != 2 || number < 0 || number > 6)) {
        invalidWord(g10, message("word_g10_supported", {wordText(g10)}));
    }
    const int slot = kind == 20 ? WorkOffsets::additionalSlot(number) : number == 0 ? WorkOffsets::kCommon : number;
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const WordValue* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)]);
        if (!w) {
            continue;
        }
        double current = offsets_.get(slot, axis);
        double value = w->value * axisUnit(axis);
        offsets_.set(slot, axis, state_.incremental() ? current + value : value);
    }
}

} // namespace m350::interp
