#include "core/macro/Executor.h"
#include "core/common/EchoText.h"
#include "core/common/Numeric.h"

#include <charconv>
#include <cmath>

namespace m350::macro {

namespace {

std::string shortest(double value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

} // namespace

Executor::Executor(const gcode::Program& program, const gcode::Dialect& dialect, VariableStore& store,
                   MachineAccess& machine, BlockSink& sink, Options options)
    : program_(program), dialect_(dialect), store_(store), machine_(machine), sink_(sink),
      options_(std::move(options)), evaluator_(program.expressions, dialect, store, machine) {
    indexHandlers();
}

void Executor::indexHandlers() {
    constexpr int kIndexed = 1000;
    gHandlers_.assign(kIndexed, -1);
    mHandlers_.assign(kIndexed, -1);
    // by the program's units rather than by the 2,000 codes: an executor is made for each MDI line
    auto index = [this](std::vector<std::int32_t>& handlers, int base, std::int32_t number, gcode::FileRole role) {
        if (base < 0 || number < base || number >= base + kIndexed) {
            return;
        }
        if (auto unit = program_.findHandler(number, role)) {
            handlers[static_cast<std::size_t>(number - base)] = static_cast<std::int32_t>(*unit);
        }
    };
    for (const gcode::ProgramUnit& unit : program_.units) {
        index(gHandlers_, dialect_.gHandlerBase, unit.number, gcode::FileRole::GLibrary);
        index(mHandlers_, dialect_.mHandlerBase, unit.number, gcode::FileRole::MLibrary);
    }
    if (dialect_.tCodeProgram >= 0) {
        tCodeUnit_ = program_.findUnit(dialect_.tCodeProgram);
    }
    indexCallingCodes();
}

bool Executor::start(std::uint32_t unit) {
    handlerCycle_.reset();
    if (unit >= program_.units.size()) {
        return false;
    }
    while (store_.localDepth() > 1) {
        store_.popLocals();
    }
    frames_.clear();
    frames_.push_back({unit, program_.units[unit].begin, 1, false, -1});
    alarm_.reset();
    hasCurrent_ = false;
    mainStarted_ = 0;
    state_ = State::Running;
    return true;
}

std::optional<gcode::SourceLocation> Executor::location() const {
    if (!hasCurrent_) {
        return std::nullopt;
    }
    return program_.blocks[current_].location;
}

bool Executor::isUserFile(std::uint32_t file) const {
    const gcode::FileRole role = program_.files[file].role;
    return role == gcode::FileRole::Main || role == gcode::FileRole::Mdi;
}

// The innermost frame of the user's program below the library frame that alarmed: its call is the
// block before its pc (the pc moves on before the callee's frame is pushed).
void Executor::nameCaller(Alarm& alarm) const {
    if (isUserFile(program_.blocks[current_].location.file) || frames_.size() < 2) {
        return;
    }
    for (std::size_t i = frames_.size() - 1; i-- > 0;) {
        const Frame& caller = frames_[i];
        const gcode::ProgramUnit& unit = program_.units[caller.unit];
        if (isUserFile(unit.file) && caller.pc > unit.begin) {
            const gcode::Block& call = program_.blocks[caller.pc - 1];
            alarm.callerFile = program_.fileName(call.location);
            alarm.callerLine = call.location.line;
            return;
        }
    }
}

void Executor::raise(AlarmCode code, std::string message) {
    Alarm alarm;
    alarm.code = code;
    alarm.message = clipEcho(std::move(message));
    if (hasCurrent_) {
        const gcode::Block& block = program_.blocks[current_];
        alarm.file = program_.fileName(block.location);
        alarm.line = block.location.line;
        alarm.column = block.location.column;
        nameCaller(alarm);
    }
    alarm_ = std::move(alarm);
    state_ = State::Alarmed;
}

void Executor::raise(AlarmCode code, const Message& words) {
    raise(code, words.english());
    alarm_->messageId = words.id;
    alarm_->messageArguments = words.arguments;
}

Executor::State Executor::step() {
    if (state_ != State::Running) {
        return state_;
    }
    if (frames_.empty()) {
        state_ = State::Finished;
        return state_;
    }
    std::size_t frameIndex = frames_.size() - 1;
    Frame& frame = frames_[frameIndex];
    if (frame.pc >= program_.units[frame.unit].end) {
        returnFromFrame(std::nullopt, 0, false); // the end of an O program returns as M99 does
        return state_;
    }
    current_ = frame.pc;
    hasCurrent_ = true;
    if (frameIndex == 0) {
        mainBlock_ = current_;
        ++mainStarted_;
    }
    const gcode::Block& block = program_.blocks[current_];
    ++blocksExecuted_;
    try {
        if (block.control == gcode::Control::None && !block.suspect && block.programNumber < 0 &&
            !(block.blockDelete && options_.blockDelete)) [[likely]] {
            executeOrdinary(block, frameIndex); // most blocks: what executeBlock() would do, one call less
        } else {
            executeBlock(block, frameIndex);
        }
    } catch (const MacroError& error) {
        raise(error.code, error.message);
        if (error.column != 0) {
            alarm_->column = error.column;
        }
        alarm_->messageId = error.messageId;
        alarm_->messageArguments = error.messageArguments;
    }
    return state_;
}

void Executor::executeBlock(const gcode::Block& block, std::size_t frameIndex) {
    using gcode::Control;
    Frame& frame = frames_[frameIndex];
    if ((block.blockDelete && options_.blockDelete) || block.programNumber >= 0) {
        ++frame.pc;
        return;
    }
    if (block.suspect) {
        const gcode::Diagnostic suspect = program_.suspectMessage(current_);
        MacroError error = MacroError::of(AlarmCode::SuspectLine, Message{suspect.messageId, suspect.messageArguments});
        error.message = suspect.message; // as the parser said it: a long echo of the line is clipped
        throw error;
    }
    switch (block.control) {
    case Control::None: executeOrdinary(block, frameIndex); return;
    case Control::Goto:
        jumpToLabel(frameIndex, evaluator_.number(block.target), program_.expressions[block.target].column);
        return;
    case Control::IfGoto:
        if (evaluator_.condition(block.condition)) {
            jumpToLabel(frameIndex, evaluator_.number(block.target), program_.expressions[block.target].column);
        } else {
            ++frame.pc;
        }
        return;
    case Control::IfThen:
        if (evaluator_.condition(block.condition)) {
            const gcode::Assignment& a = block.assignments.front();
            int number = evaluator_.variableNumber(a.index);
            evaluator_.writeVariable(number, evaluator_.evaluate(a.value), a.text, a.column);
        }
        ++frames_[frameIndex].pc;
        return;
    case Control::While:
        if (block.partner < 0) {
            throw MacroError::of(AlarmCode::WhileWithoutEnd,
                                 message("loop_no_end", {gcode::loopOpening(block), std::to_string(block.loopId)}),
                                 block.controlColumn);
        }
        if (block.condition == gcode::kNoExpr || evaluator_.condition(block.condition)) {
            ++frame.pc;
        } else {
            frame.pc = static_cast<std::uint32_t>(block.partner) + 1;
        }
        return;
    case Control::End:
        if (block.partner < 0) {
            throw MacroError::of(AlarmCode::EndWithoutDo, message("loop_end_no_do", {std::to_string(block.loopId)}),
                                 block.controlColumn);
        }
        frame.pc = static_cast<std::uint32_t>(block.partner);
        return;
    case Control::Popen:
    case Control::Pclos:
    case Control::Dprnt:
    case Control::Bprnt:
    case Control::MSetData:
    case Control::MGetData:
    case Control::ModbusConversion:
        if (executeDeviceStatement(block)) {
            ++frame.pc;
        }
        return;
    }
}

void Executor::jumpToLabel(std::size_t frameIndex, double label, std::uint32_t column) {
    Frame& frame = frames_[frameIndex];
    const gcode::ProgramUnit& unit = program_.units[frame.unit];
    if (!(std::round(label) >= 0 && std::round(label) <= gcode::kMaxLabel)) { // NaN too
        throw MacroError::of(AlarmCode::GotoMissingLabel,
                             message("goto_range", {shortest(label), std::to_string(gcode::kMaxLabel)}), column);
    }
    auto n = roundToInt(label);
    if (auto target = program_.findLabel(frame.unit, n, frame.pc)) {
        frame.pc = *target;
        return;
    }
    std::string where = unit.number >= 0 ? "O" + std::to_string(unit.number) : bilingual("this program", "本程序");
    throw MacroError::of(AlarmCode::GotoMissingLabel, message("flow_goto_no_label", {std::to_string(n), where}), column);
}

void Executor::returnFromFrame(std::optional<double> label, std::uint32_t column, bool explicitM99) {
    Frame& frame = frames_.back();
    if (frames_.size() == 1 && explicitM99 && dialect_.m99RestartsMain) {
        // FANUC: M99 in the main program runs it again (from label P when given), until M30 or a stop
        frame.pc = program_.units[frame.unit].begin;
        if (label) {
            jumpToLabel(0, *label, column);
        }
        return;
    }
    if (frame.repeatsLeft > 1) {
        --frame.repeatsLeft;
        frame.pc = program_.units[frame.unit].begin;
        return;
    }
    if (frame.ownsLocals) {
        store_.popLocals();
    }
    frames_.pop_back();
    if (frames_.empty()) {
        state_ = State::Finished;
        return;
    }
    if (label) {
        // M99 P<n>: back to label n of the caller instead of the block after the call
        jumpToLabel(frames_.size() - 1, *label, column);
    }
}

bool Executor::handlingCode(std::int32_t code) const {
    for (const Frame& f : frames_) {
        if (f.handledCode == code) {
            return true;
        }
    }
    return false;
}

namespace {

// How a program was called, in both languages (programUnit's `how`).
std::string callWords(std::string_view how) {
    if (how == "address call") return bilingual(how, "地址调用");
    if (how == "M code program") return bilingual(how, "M代码程序");
    if (how == "G code program") return bilingual(how, "G代码程序");
    return std::string(how); // G65, M98
}

} // namespace

std::uint32_t Executor::programUnit(double number, const char* how, std::uint32_t column) const {
    auto n = roundToInt(number);
    if (auto unit = program_.findUnit(n)) {
        return *unit;
    }
    throw MacroError::of(AlarmCode::UnknownProgram, message("unknown_program", {callWords(how), std::to_string(n)}),
                         column);
}

void Executor::pushCall(const Call& call, std::uint32_t column) {
    if (frames_.size() > static_cast<std::size_t>(dialect_.maxCallDepth)) {
        throw MacroError::of(AlarmCode::CallNestingTooDeep,
                             message("call_nesting", {std::to_string(dialect_.maxCallDepth)}), column);
    }
    if (call.repeats <= 0) {
        return;
    }
    if (call.opensLocals) {
        store_.pushLocals();
        for (auto [variable, value] : call.arguments) {
            store_.write(store_.map().describe(variable), variable, Value::of(value));
        }
    }
    frames_.push_back({call.unit, program_.units[call.unit].begin, call.repeats, call.opensLocals, call.handledCode});
}

} // namespace m350::macro
