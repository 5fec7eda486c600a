#include "core/interp/ModalInterpreter.h"
#include "core/common/Message.h"
#include "core/common/Numeric.h"

#include "core/params/IoPorts.h"
#include "core/params/ParameterNumbers.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace m350::interp {

using macro::BlockOutcome;
using macro::MacroError;
using macro::WordValue;

namespace {

// Which modal group a G code sets, -1 for non-modal codes handled elsewhere.
int groupOf(int code) {
    switch (code) {
    case 0: case 1: case 2: case 3: return 1;
    case 17: case 18: case 19: return 2;
    case 90: case 91: return 3;
    case 94: case 95: return 5;
    case 20: case 21: return 6;
    case 40: case 41: case 42: return 7;
    case 43: case 44: case 49: return 8;
    case 73: case 74: case 80: case 81: case 82: case 83: case 84: return 9;
    case 98: case 99: return 10;
    case 54: case 55: case 56: case 57: case 58: case 59: return 14;
    case 68: case 69: return 16;
    default: return -1;
    }
}

} // namespace

ModalInterpreter::ModalInterpreter(const gcode::Dialect& dialect, params::ParameterTable& parameters,
                                   WorkOffsets& offsets, tools::ToolData& tools,
                                   machine::MachineInterface& machine)
    : dialect_(dialect), parameters_(parameters), offsets_(offsets), tools_(tools), machine_(machine) {
    state_.feed = parameters_.get(param::kDefaultFeed);
    state_.spindleSpeed = parameters_.get(param::kDefaultSpindleSpeed); // M3 before any S
}

// FANUC reads the offset when G43/G44 or an H word under them is given (parameter EVO = 0), and
// LinuxCNC when G43 is: changing the offset of the active H moves nothing until then.
void ModalInterpreter::latchLengthOffset(const Words& words) {
    const int mode = state_.group(8);
    if ((mode == 43 || mode == 44) && (words.hasG(43) || words.hasG(44) || words.has('H'))) {
        state_.lengthOffsetValue = tools_.lengthOffset(state_.lengthOffset);
    }
}

void ModalInterpreter::applyLengthOffset(int number) {
    state_.groups[8] = 43;
    state_.lengthOffset = number;
    state_.lengthOffsetValue = tools_.lengthOffset(number);
}

machine::Axes ModalInterpreter::workPosition() const {
    return machine_.position() - workOffset();
}

macro::BlockSink::CycleContext ModalInterpreter::cycleContext() const {
    CycleContext context;
    machine::Axes work = workPosition();
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        context.work[static_cast<std::size_t>(axis)] = work(axis) / axisUnit(axis);
    }
    context.incremental = state_.incremental();
    context.returnToR = state_.group(10) == 99;
    return context;
}

std::optional<ModalInterpreter::OperatorStop> ModalInterpreter::takeMadeStop() {
    std::optional<OperatorStop> out;
    out.swap(stop_);
    return out;
}

void ModalInterpreter::stopForOperator(OperatorStop::Kind kind, std::string what) {
    stop_ = OperatorStop{kind, std::move(what), block_ ? block_->location : gcode::SourceLocation{}};
}

BlockOutcome ModalInterpreter::execute(const macro::EvaluatedBlock& block) {
    Words& words = words_; // reused across blocks
    words.reset(block);
    block_ = block.source;
    dynamicLength_ = false;
    if (block.repeated >= 0) {
        const WordValue& w = block.words[static_cast<std::size_t>(block.repeated)];
        return {false, MacroError::of(AlarmCode::InvalidWord, message("word_twice", {std::string(1, w.letter)}),
                                      w.column)};
    }
    try {
        // An address the M350 has no use for (no axis, no argument of its call specification) was
        // ignored in silence: `G1 X10 E5` moved X and dropped E. A FANUC refuses a word its control
        // does not know with alarm PS0009 (improper NC-address); so does the M350 here.
        constexpr std::uint32_t kNoM350Address =
            Words::bit('E') | Words::bit('U') | Words::bit('V') | Words::bit('W');
        if (dialect_.id == gcode::DialectId::M350 && (words.present & kNoM350Address) != 0) [[unlikely]] {
            for (char letter : {'E', 'U', 'V', 'W'}) {
                if (const WordValue* w = words.find(letter)) {
                    throw MacroError::of(AlarmCode::InvalidWord,
                                         message("improper_address", {wordText(*w),
                                                                      std::string(1, letter)}),
                                         w->column);
                }
            }
        }
        // 1. F S T H D; F in the unit this block sets (`G20 G1 X1 F10`: 10 inch/min)
        constexpr std::uint32_t kModalLetters =
            Words::bit('F') | Words::bit('S') | Words::bit('T') | Words::bit('H') | Words::bit('D');
        if ((words.present & kModalLetters) != 0) {
            if (words.find('F')) {
                if (words.find('F')->value < 0) {
                    invalidWord(*words.find('F'), message("word_negative_feed", {wordText(*words.find('F'))}));
                }
                const bool inches = words.hasG(20) || (state_.inches() && !words.hasG(21));
                state_.feed = words.find('F')->value * (inches ? 25.4 : 1.0);
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
            case 8: case 9:
                machine_.coolant(code == 8);
                if (dialect_.id == gcode::DialectId::M350) {
                    switchFunctionOutput(param::kCoolantOutput, code == 8, param::kCoolantResponse);
                }
                break;
            case 0: case 1: case 2: case 30: case 6: break; // handled after motion (M6: empty on the M350)
            case 10: case 11:
                if (dialect_.id == gcode::DialectId::M350) { // 润滑 lubrication, the firmware's own
                    switchFunctionOutput(param::kLubricationOutput, code == 10, param::kLubricationResponse);
                    break;
                }
                machine_.auxiliary(code); // FANUC: the PMC's (the umbrella carousel's clamp)
                break;
            case 61:
                if (dialect_.id != gcode::DialectId::M350) {
                    setToolNumber(m, words);
                    break;
                }
                [[fallthrough]];
            default:
                if (!knowsMCode(dialect_, code)) {
                    invalidWord(m, unknownMCodeWords(dialect_, code, wordText(m)));
                }
                machine_.auxiliary(code); // FANUC: an M code the PMC answers (magazine, clamp ...)
                break;
            }
        }
        // 3-6: modal codes and the non-modal ones. Most blocks hold one motion code (G0-G3) and no
        // other, which sets group 1 and ends any canned cycle, as applyGCodes() would.
        constexpr std::uint64_t kMotionCodes = 0b1111;
        if (words.g.size() == 1 && words.gCodes[1] == 0 && words.gCodes[0] != 0 &&
            (words.gCodes[0] & ~kMotionCodes) == 0) {
            state_.groups[1] = std::countr_zero(words.gCodes[0]);
            cancelCycle();
        } else {
            applyGCodes(words);
        }
        latchLengthOffset(words);
        // 7. motion
        if (!std::exchange(dynamicLength_, false)) [[likely]] {
            moveAxes(words);
            if (state_.rotating()) [[unlikely]] {
                noteAbsoluteCommand(words);
            }
        }
        // 8. stops and program end
        for (const WordValue& m : words.m) {
            int code = roundToInt(m.value);
            if (code == 0) {
                stopForOperator(OperatorStop::Kind::Program, "M00 program stop");
            } else if (code == 1) {
                stopForOperator(OperatorStop::Kind::Optional, "M01 optional stop");
            } else if (code == 6 && dialect_.id != gcode::DialectId::M350) {
                toolChange_ = ToolChange{state_.selectedTool, false};
            } else if (code == 2 || code == 30) {
                flushCompensation();
                compensation_.reset();
                state_.groups[7] = 40;
                state_.groups[16] = 69; // a FANUC reset cancels the rotation
                cancelCycle();
                machine_.spindle(machine::SpindleState::Stop, 0.0);
                machine_.coolant(false);
                if (dialect_.id == gcode::DialectId::M350) { // as the factory's M30 handler's M5M9M11
                    switchFunctionOutput(param::kCoolantOutput, false, std::nullopt);
                    switchFunctionOutput(param::kLubricationOutput, false, std::nullopt);
                }
                if (code == 30 && dialect_.id == gcode::DialectId::M350) { // 总加工数, 加工件数
                    parameters_.set(param::kTotalRunCount, parameters_.get(param::kTotalRunCount) + 1);
                    parameters_.set(param::kPieceCount, parameters_.get(param::kPieceCount) + 1);
                }
                endProgram = true;
            }
        }
        return {endProgram, std::nullopt};
    } catch (const MacroError& error) {
        return {false, error};
    }
}

// M8/M9 and M10/M11 on the M350 switch their function's output (its IO triple: pin, enable,
// active level; nothing when it is not enabled). When the output changes, the block lasts the
// command's response time (params 92, 94, seconds) for the pump or valve it drives, as the
// spindle's start delay holds the block after M3; a command that changes nothing waits for nothing.
void ModalInterpreter::switchFunctionOutput(int outputTriple, bool on, std::optional<int> responseParameter) {
    const params::PortAssignment port = params::portAssignment(parameters_, outputTriple);
    if (!port.wired() || port.pin > machine::kOutputCount) {
        return;
    }
    const int level = on ? port.activeLevel : 1 - port.activeLevel;
    if (machine_.output(port.pin) == level) {
        return;
    }
    machine_.setOutput(port.pin, level);
    if (responseParameter) {
        const double seconds = parameters_.get(*responseParameter);
        if (seconds > 0.0 && std::isfinite(seconds)) {
            machine_.dwell(seconds);
        }
    }
}

namespace {

bool isAdditionalSystemCode(double value) { return std::abs(value - 54.1) < 1e-6; } // G54.1

} // namespace

bool ModalInterpreter::knowsMCode(const gcode::Dialect& dialect, int code) {
    if (dialect.id != gcode::DialectId::M350) {
        return true;
    }
    switch (code) { // the cases of execute()'s M switch that do not end in its default
    case 0: case 1: case 2: case 3: case 4: case 5: case 6: case 8: case 9: case 10: case 11: case 19: case 30:
        return true;
    default: return false;
    }
}

Message ModalInterpreter::unknownMCodeWords(const gcode::Dialect& dialect, int code, const std::string& word) {
    const std::optional<std::int32_t> handler = dialect.handlerProgram('M', code);
    return handler ? message("word_unknown_m_handler", {word, std::to_string(*handler)})
                   : message("word_unknown_m", {word});
}

bool ModalInterpreter::knowsGCode(const gcode::Dialect& dialect, const CoordinateFeatures& features, double value) {
    if (dialect.lookAheadCodes && isLookAheadCode(value)) {
        return true;
    }
    if (isAdditionalSystemCode(value)) {
        return features.additionalSystems > 0;
    }
    if (dialect.id != gcode::DialectId::M350 && std::abs(value - 43.1) < 1e-6) {
        return true; // LinuxCNC's dynamic tool length, where the machine keeps a tool.tbl
    }
    const int code = roundToInt(value);
    if (std::abs(value - code) > 1e-6) {
        return false;
    }
    switch (code) {
    case 4: case 10: case 28: case 30: case 31: case 52: case 53: case 92: return true; // applyGCodes, moveAxes
    case 68: case 69: return features.rotation;
    default: return groupOf(code) > 0;
    }
}

void ModalInterpreter::applyGCodes(const Words& words) {
    if (state_.rotating() || words.hasG(68)) [[unlikely]] {
        refuseUnderRotation(words);
    }
    std::array<bool, 23> seen{};
    const WordValue* g68 = nullptr;
    for (const WordValue& g : words.g) {
        if (dialect_.lookAheadCodes && lookAheadCode(g, words)) {
            continue;
        }
        const double value = g.value;
        if (std::abs(value - 43.1) < 1e-6 && dialect_.id != gcode::DialectId::M350) {
            setDynamicLength(g, words);
            continue;
        }
        if (isAdditionalSystemCode(value)) [[unlikely]] {
            if (seen[14]) {
                invalidWord(g, message("word_same_group", {wordText(g)}));
            }
            seen[14] = true;
            selectAdditionalSystem(words, g);
            continue;
        }
        int code = 0;
        if (value >= 0 && value < 128 && value == static_cast<double>(static_cast<int>(value))) {
            code = static_cast<int>(value); // as written, most codes: no rounding
        } else {
            code = roundToInt(value);
            if (std::abs(value - code) > 1e-6) {
                invalidWord(g, message("word_unknown_g", {wordText(g)}));
            }
        }
        int group = groupOf(code);
        if (group > 0) {
            if (seen[static_cast<std::size_t>(group)]) {
                invalidWord(g, message("word_same_group", {wordText(g)}));
            }
            seen[static_cast<std::size_t>(group)] = true;
            if (group == 16) {
                if (!features_.rotation) {
                    invalidWord(g, message("word_unknown_g", {wordText(g)}));
                }
                if (code == 68) {
                    g68 = &g; // after the block's plane, units and distance mode
                    continue;
                }
            }
            state_.groups[static_cast<std::size_t>(group)] = code;
            if (group == 14) {
                state_.additionalSystem = 0;
            }
            if (group == 14 && dialect_.id == gcode::DialectId::M350) {
                parameters_.set(param::kCurrentWorkSystem, code - 53);
            }
            if ((code == 43 || code == 44) && dialect_.id == gcode::DialectId::M350) {
                invalidWord(g, message("word_m350_no_h_offset", {wordText(g)}));
            }
            continue;
        }
        switch (code) {
        case 4: {
            double seconds = 0.0;
            if (words.find('P')) {
                if (words.find('P')->value == -1 && dialect_.id == gcode::DialectId::M350) {
                    stopForOperator(OperatorStop::Kind::WaitForStart, "G04 P-1 waits for START");
                    break;
                }
                if (words.find('P')->value < 0) {
                    invalidWord(*words.find('P'), message(dialect_.id == gcode::DialectId::M350 ? "word_negative_dwell_m350"
                                                                                            : "word_negative_dwell",
                                                      {wordText(*words.find('P'))}));
                }
                seconds = words.find('P')->value * dialect_.dwellPScale;
            } else if (words.find('X') && dialect_.dwellXSeconds) {
                seconds = words.find('X')->value;
            } else {
                invalidWord(g, message(dialect_.dwellXSeconds ? "word_g04_needs_p_or_x" : "word_g04_needs_p", {wordText(g)}));
            }
            machine_.dwell(seconds);
            break;
        }
        case 10: case 28: case 30: case 31: case 52: case 53: case 92: break; // with the axis words, in moveAxes
        default: invalidWord(g, message("word_unknown_g", {wordText(g)}));
        }
    }
    if (seen[1] && seen[9] && state_.group(9) != 80) {
        auto cycle = std::find_if(words.g.begin(), words.g.end(),
                                  [](const WordValue& w) { return groupOf(roundToInt(w.value)) == 9; });
        invalidWord(*cycle, message("word_motion_cancels_cycle", {wordText(*cycle)}));
    }
    if (seen[1] || (seen[9] && state_.group(9) == 80)) {
        cancelCycle(); // a cycle begun again starts from new drilling data and a new initial level
    }
    if (g68) [[unlikely]] {
        startRotation(words, *g68);
    }
}

// G54.1 Pn selects additional work system n; without P, P1 (as GSK's FANUC-compatible 980MDc
// documents it).
void ModalInterpreter::selectAdditionalSystem(const Words& words, const WordValue& g) {
    if (features_.additionalSystems <= 0) {
        invalidWord(g, message("word_unknown_g", {wordText(g)}));
    }
    const WordValue* p = words.find('P');
    const double number = p ? p->value : 1.0;
    const int systems = features_.additionalSystems;
    if (number != std::round(number) || number < 1 || number > systems) {
        invalidWord(p ? *p : g, message("word_g54_1_range", {wordText(p ? *p : g), std::to_string(systems)}));
    }
    state_.groups[14] = 54.1;
    state_.additionalSystem = static_cast<int>(number);
}

} // namespace m350::interp
