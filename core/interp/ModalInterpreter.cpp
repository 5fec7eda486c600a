#include "core/interp/ModalInterpreter.h"
#include "core/common/Numeric.h"

#include "core/config/ParameterNumbers.h"

#include <cmath>

namespace m350::interp {

using macro::BlockOutcome;
using macro::MacroError;
using macro::WordValue;
namespace param = config::param;


namespace {

std::string codeText(char letter, double value) {
    double whole = std::round(value);
    if (std::abs(value - whole) < 1e-9) {
        return std::string(1, letter) + std::to_string(saturatingInt(whole));
    }
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);
    return std::string(1, letter) + text;
}

[[noreturn]] void invalid(const WordValue& w, std::string why) {
    throw MacroError{AlarmCode::InvalidWord, codeText(w.letter, w.value) + ": " + why, w.column};
}

// Which modal group a G code sets, -1 for non-modal codes handled elsewhere.
int groupOf(int code) {
    switch (code) {
    case 0: case 1: case 2: case 3: return 1;
    case 17: case 18: case 19: return 2;
    case 90: case 91: return 3;
    case 94: case 95: return 5;
    case 20: case 21: return 6;
    case 40: return 7;
    case 49: return 8;
    case 80: return 9;
    case 98: case 99: return 10;
    case 54: case 55: case 56: case 57: case 58: case 59: return 14;
    default: return -1;
    }
}

} // namespace

ModalInterpreter::ModalInterpreter(const gcode::Dialect& dialect, config::ParameterTable& parameters,
                                   WorkOffsets& offsets, machine::MachineInterface& machine)
    : dialect_(dialect), parameters_(parameters), offsets_(offsets), machine_(machine) {
    state_.feed = parameters_.get(param::kDefaultFeed);
}

int ModalInterpreter::currentTool() const {
    return dialect_.id == gcode::DialectId::M350 ? saturatingInt(parameters_.get(param::kCurrentTool))
                                                  : state_.selectedTool;
}

double ModalInterpreter::toolZOffset() const {
    if (dialect_.id != gcode::DialectId::M350) {
        return 0.0;
    }
    int tool = currentTool();
    int capacity = saturatingInt(parameters_.get(param::kMagazineCapacity));
    if (tool >= 1 && tool <= capacity && tool <= param::kToolZOffsetCount) {
        return parameters_.get(param::kToolZOffsetFirst + tool - 1);
    }
    int virtualIndex = tool - capacity;
    if (tool > capacity && virtualIndex >= 1 && virtualIndex <= param::kVirtualToolZOffsetCount) {
        return parameters_.get(param::kVirtualToolZOffsetFirst + virtualIndex - 1);
    }
    return 0.0;
}

int ModalInterpreter::activeSlot() const {
    if (dialect_.id == gcode::DialectId::M350) {
        int slot = saturatingInt(parameters_.get(param::kCurrentWorkSystem));
        return (slot >= 0 && slot <= 6) ? slot : 1;
    }
    return state_.group(14) - 53;
}

machine::Axes ModalInterpreter::workOffset() const {
    machine::Axes offset = offsets_.slot(activeSlot()) + offsets_.slot(WorkOffsets::kG52) +
                           offsets_.slot(WorkOffsets::kCommon);
    if (dialect_.id == gcode::DialectId::Fanuc) {
        offset += offsets_.slot(WorkOffsets::kG92); // FANUC's G92 shifts the active system
    }
    offset(2) += toolZOffset(); // M350: work Z = machine Z - G54..G59 Z - tool Z offset
    return offset;
}

machine::Axes ModalInterpreter::workPosition() const {
    return machine_.position() - workOffset();
}

std::vector<std::string> ModalInterpreter::takeNotices() {
    std::vector<std::string> out;
    out.swap(notices_);
    return out;
}

BlockOutcome ModalInterpreter::execute(const macro::EvaluatedBlock& block) {
    Words& words = words_; // reused across blocks
    words.clear();
    for (const WordValue& w : block.words) {
        if (w.letter == 'G') {
            words.g.push_back(w);
            continue;
        }
        if (w.letter == 'M') {
            words.m.push_back(w);
            continue;
        }
        if (words.has(w.letter)) {
            return {false, MacroError{AlarmCode::InvalidWord,
                                      std::string(1, w.letter) + " appears twice in one block", w.column}};
        }
        words.letter[static_cast<std::size_t>(w.letter - 'A')] = w;
        words.present |= Words::bit(w.letter);
    }
    try {
        // 1. F S T H D
        double unit = state_.inches() ? 25.4 : 1.0;
        if (words.find('F')) {
            if (words.find('F')->value < 0) {
                invalid(*words.find('F'), "the feed cannot be negative");
            }
            state_.feed = words.find('F')->value * unit;
        }
        if (words.find('S')) {
            state_.spindleSpeed = words.find('S')->value;
        }
        if (words.find('T')) {
            state_.selectedTool = roundToInt(words.find('T')->value);
        }
        if (words.find('H')) {
            state_.lengthOffset = roundToInt(words.find('H')->value);
        }
        if (words.find('D')) {
            state_.radiusOffset = roundToInt(words.find('D')->value);
        }
        // 2. spindle and coolant
        bool endProgram = false;
        for (const WordValue& m : words.m) {
            int code = roundToInt(m.value);
            state_.lastM = m.value;
            switch (code) {
            case 3: machine_.spindle(machine::SpindleState::Forward, state_.spindleSpeed); break;
            case 4: machine_.spindle(machine::SpindleState::Reverse, state_.spindleSpeed); break;
            case 5: machine_.spindle(machine::SpindleState::Stop, 0.0); break;
            case 19: machine_.spindle(machine::SpindleState::Orient, 0.0); break;
            case 8: machine_.coolant(true); break;
            case 9: machine_.coolant(false); break;
            case 0: case 1: case 2: case 30: case 6: break; // handled after motion (M6: empty on the M350)
            default:
                if (dialect_.id == gcode::DialectId::M350) {
                    invalid(m, "no such M code (and no O" + std::to_string(dialect_.mHandlerBase + code) +
                                   " handler in slib-m.nc)");
                }
                break; // FANUC: an M code the PMC answers (magazine, clamp ...)
            }
        }
        // 3-6: modal codes and the non-modal ones
        applyGCodes(words);
        // 7. motion
        moveAxes(words);
        // 8. stops and program end
        for (const WordValue& m : words.m) {
            int code = roundToInt(m.value);
            if (code == 0) {
                notices_.push_back("M0 program stop (headless run: continued)");
            } else if (code == 2 || code == 30) {
                machine_.spindle(machine::SpindleState::Stop, 0.0);
                machine_.coolant(false);
                endProgram = true;
            }
        }
        return {endProgram, std::nullopt};
    } catch (const MacroError& error) {
        return {false, error};
    }
}

void ModalInterpreter::applyGCodes(const Words& words) {
    std::array<bool, 23> seen{};
    for (const WordValue& g : words.g) {
        double value = g.value;
        int code = roundToInt(value);
        if (std::abs(value - code) > 1e-6) {
            invalid(g, "not a G code this machine knows");
        }
        int group = groupOf(code);
        if (group > 0) {
            if (seen[static_cast<std::size_t>(group)]) {
                invalid(g, "two G codes of the same group in one block");
            }
            seen[static_cast<std::size_t>(group)] = true;
            state_.groups[static_cast<std::size_t>(group)] = code;
            if (group == 14 && dialect_.id == gcode::DialectId::M350) {
                parameters_.set(param::kCurrentWorkSystem, code - 53);
            }
            continue;
        }
        switch (code) {
        case 4: {
            double seconds = 0.0;
            if (words.find('P')) {
                if (words.find('P')->value < 0) { // M350 `G04 P-1`: wait for START
                    notices_.push_back("G04 P-1 waits for START (headless run: continued)");
                    break;
                }
                seconds = words.find('P')->value * dialect_.dwellPScale;
            } else if (words.find('X') && dialect_.dwellXSeconds) {
                seconds = words.find('X')->value;
            } else {
                invalid(g, "G04 needs P<milliseconds>" + std::string(dialect_.dwellXSeconds ? " or X<seconds>" : ""));
            }
            machine_.dwell(seconds);
            break;
        }
        case 28: case 53: case 92: break; // with the axis words, in moveAxes
        default: invalid(g, "not a G code this machine knows");
        }
    }
}

machine::Axes ModalInterpreter::targetFor(const Words& words, bool machineCoordinates) const {
    machine::Axes target = machine_.position();
    machine::Axes offset = workOffset();
    double unit = state_.inches() ? 25.4 : 1.0;
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const auto* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)]);
        if (!w) {
            continue;
        }
        double v = w->value * (axis < 3 ? unit : 1.0);
        if (machineCoordinates) {
            target(axis) = v;
        } else if (state_.incremental()) {
            target(axis) += v;
        } else {
            target(axis) = v + offset(axis);
        }
    }
    return target;
}

void ModalInterpreter::moveAxes(const Words& words) {
    if (words.hasG(92)) {
        // G92: the current position gets the given work coordinates
        machine::Axes position = machine_.position();
        machine::Axes offset = workOffset();
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            if (const auto* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)])) {
                int slot = dialect_.id == gcode::DialectId::M350 ? activeSlot() : WorkOffsets::kG92;
                double current = offsets_.get(slot, axis);
                offsets_.set(slot, axis, current + (position(axis) - offset(axis)) - w->value);
            }
        }
        return;
    }
    if (!words.hasAxis() || words.hasG(4)) {
        return; // in a G04 block, X is the dwell time (FANUC), not a move
    }
    if (words.hasG(53)) {
        // One-shot machine coordinates; with F (the M350's `G53 Z#1306 F#1312`) a feed move
        if (words.find('F')) {
            machine_.feed(targetFor(words, true), state_.feed);
        } else {
            machine_.rapid(targetFor(words, true));
        }
        return;
    }
    if (words.hasG(28)) {
        // via the intermediate point to the position after homing (params 122-126), as the M350 does
        machine_.rapid(targetFor(words, false));
        machine::Axes home = machine_.position();
        for (int axis = 0; axis < machine::kAxisCount; ++axis) {
            if (words.find(machine::kAxisNames[static_cast<std::size_t>(axis)])) {
                home(axis) = parameters_.get(param::kHomePositionX + axis);
            }
        }
        machine_.rapid(home);
        return;
    }
    machine::Axes target = targetFor(words, false);
    switch (state_.group(1)) {
    case 0: machine_.rapid(target); break;
    case 1:
        if (state_.feed <= 0) {
            throw MacroError{AlarmCode::InvalidWord, "G01 with no feed: give F", words.g.empty() ? 0 : words.g[0].column};
        }
        machine_.feed(target, state_.feed);
        break;
    default: {
        // G2/G3: the end point now; arc geometry arrives with the motion model
        machine_.arc(target, machine_.position(), machine::Plane::XY, state_.group(1) == 2, 0, state_.feed);
        break;
    }
    }
}

} // namespace m350::interp
