// The part of the Executor that runs ordinary blocks: assignments, then the block's words, of which
// calls (M98, G65, M99, T, and codes that have handler programs) are taken out first.
#include "core/macro/Executor.h"
#include "core/common/Numeric.h"

#include <algorithm>
#include <cmath>

namespace m350::macro {

namespace {

constexpr std::int32_t codeKey(char letter, int number) {
    return (static_cast<std::int32_t>(letter) << 16) | (number & 0xFFFF);
}

bool isCode(const WordValue& w, char letter, int number) {
    return w.letter == letter && std::abs(w.value - number) < 1e-9;
}

bool wholeNumber(double v) {
    return std::abs(v - std::round(v)) < 1e-9 && v >= 0 && v < 65536;
}

// `M98 P501 X<axis>` without an O501 anywhere: the axis the firmware's own homing is asked for.
int builtInHomingAxis(std::vector<WordValue>& words, std::uint32_t column) {
    auto x = std::find_if(words.begin(), words.end(), [](const WordValue& w) { return w.letter == 'X'; });
    if (x == words.end() || !wholeNumber(x->value) || x->value > 4) {
        throw MacroError::of(AlarmCode::InvalidArgument, message("homing_call_axis"), column);
    }
    int axis = roundToInt(x->value);
    words.erase(x);
    return axis;
}

} // namespace

bool Executor::inCodeCall() const {
    for (const Frame& f : frames_) {
        if (f.handledCode != -1) {
            return true;
        }
    }
    return false;
}

const CodeCall* Executor::configuredCall(char letter, int code) const {
    if (options_.callCodes.empty()) {
        return nullptr;
    }
    const CodeCall* call = options_.callCodes.find(letter, code);
    return call && (dialect_.codeCallsNest || !inCodeCall()) ? call : nullptr;
}

// `G00X123Y456B100` with parameter 6090 = 66 (B): the block moves X and Y, then O9004 runs as a
// subprogram with #146 = 100.
void Executor::takeAddressCalls(std::vector<WordValue>& words, std::vector<Call>& calls, std::uint32_t& callColumn) {
    if (!dialect_.codeCallsNest && inCodeCall()) {
        return; // inside a program a code called, the address is an ordinary one
    }
    for (std::size_t i = 0; i < words.size();) {
        const WordValue w = words[i];
        const CodeCall* call = options_.callCodes.address(w.letter);
        const std::int32_t key = codeKey(w.letter, 0xFFFF);
        if (call == nullptr || handlingCode(key)) {
            ++i;
            continue;
        }
        words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
        evaluator_.writeVariable(call->valueVariable, Value::of(w.value), {}, w.column);
        calls.push_back(Call{programUnit(call->program, "address call", w.column), 1, dialect_.m98OpensLocalLevel, key, {}});
        callColumn = w.column;
    }
}

bool Executor::changingToolInCall() const {
    return handlingCode(codeKey('T', 0)) || handlingCode(codeKey('M', 6));
}

// Moves the words the argument specification maps into `out` (local number, value). G65 and M98
// take every letter mapped (FANUC: M#13, T#20); a handler called for a G or M code leaves the
// block's other codes alone.
void Executor::takeArguments(std::vector<WordValue>& words, const std::array<std::int8_t, 26>& map,
                             std::vector<std::pair<int, double>>& out, bool codesAreArguments) {
    std::vector<WordValue> kept;
    for (const WordValue& w : words) {
        int variable = map[static_cast<std::size_t>(w.letter - 'A')];
        bool code = w.letter == 'G' || w.letter == 'M' || w.letter == 'T';
        if (variable >= 0 && w.letter != 'N' && (codesAreArguments || !code)) {
            out.emplace_back(variable, w.value);
        } else {
            kept.push_back(w);
        }
    }
    words = std::move(kept);
}

std::optional<std::uint32_t> Executor::handlerFor(char letter, int code) const {
    const auto& table = letter == 'M' ? mHandlers_ : gHandlers_;
    if (code >= 0 && static_cast<std::size_t>(code) < table.size()) {
        std::int32_t unit = table[static_cast<std::size_t>(code)];
        return unit < 0 ? std::nullopt : std::optional<std::uint32_t>(static_cast<std::uint32_t>(unit));
    }
    const std::optional<std::int32_t> handler = dialect_.handlerProgram(letter, code);
    if (!handler) {
        return std::nullopt;
    }
    return program_.findHandler(*handler, letter == 'M' ? gcode::FileRole::MLibrary : gcode::FileRole::GLibrary);
}

// The whole codes 0-127 that start a call (G65, M98, M99, the machine's mapped codes and those
// with handler programs), so that mayCall() meets a block's codes with them in two tests.
void Executor::indexCallingCodes() {
    addressLetters_ = options_.callCodes.addressLetters();
    for (int code = 0; code < CodeBits::kCodes; ++code) {
        auto calls = [this, code](char letter) {
            return options_.callCodes.find(letter, code) != nullptr || handlerFor(letter, code).has_value();
        };
        if (code == 65 || calls('G')) {
            callingG_.add(code);
        }
        if (code == 98 || code == 99 || calls('M')) {
            callingM_.add(code);
        }
    }
}

// mayCall() for any block.
bool Executor::mayCallInFull(const EvaluatedBlock& block) const {
    if (handlerCycle_ && !handlingCode(handlerCycle_->key)) {
        return true; // a block may repeat or end the modal cycle
    }
    if (block.has('T') && tCodeUnit_ && !handlingCode(codeKey('T', 0))) {
        return true;
    }
    if ((block.letters & addressLetters_) != 0) {
        return true;
    }
    if (block.otherCodes) {
        return otherCodeMayCall(block);
    }
    return block.gCodes.meets(callingG_) || block.mCodes.meets(callingM_);
}

// A block with a G or M word that is not a whole code 0-127: each word asked in turn.
bool Executor::otherCodeMayCall(const EvaluatedBlock& block) const {
    for (const WordValue& w : block.words) {
        switch (w.letter) {
        case 'G':
        case 'M': {
            // Most codes are written as whole numbers (G1 is 1.0 exactly): no rounding needed.
            const bool exact = w.value >= 0 && w.value < 65536 && w.value == static_cast<double>(static_cast<int>(w.value));
            if (!exact && !wholeNumber(w.value)) {
                break;
            }
            const auto code = exact ? static_cast<int>(w.value) : static_cast<int>(std::round(w.value));
            if ((w.letter == 'G' && code == 65) || (w.letter == 'M' && (code == 98 || code == 99)) ||
                (!options_.callCodes.empty() && options_.callCodes.find(w.letter, code) != nullptr) ||
                handlerFor(w.letter, code)) {
                return true;
            }
            break;
        }
        default: break;
        }
    }
    return false;
}

// Hands the block's remaining words to the modal interpreter and moves to the next block.
// False when the program ended (M30, M02).
bool Executor::sendToSink(const EvaluatedBlock& block, std::size_t frameIndex) {
    if (!block.words.empty()) {
        ++machineBlocks_;
        BlockOutcome outcome = sink_.execute(block);
        if (outcome.error) {
            throw *outcome.error;
        }
        if (outcome.endProgram) {
            while (store_.localDepth() > 1) {
                store_.popLocals();
            }
            frames_.clear();
            state_ = State::Finished;
            return false;
        }
    }
    ++frames_[frameIndex].pc;
    return true;
}

void Executor::executeOrdinary(const gcode::Block& block, std::size_t frameIndex) {
    for (const gcode::Assignment& a : block.assignments) {
        int number = evaluator_.variableNumber(a.index);
        evaluator_.writeVariable(number, evaluator_.evaluate(a.value), a.text, a.column);
    }
    if (block.words.empty()) {
        ++frames_[frameIndex].pc;
        return;
    }
    EvaluatedBlock& evaluated = scratch_; // reused: executing a block allocates nothing
    if (!evaluated.assignNumbers(block)) {
        evaluated.clear(block);
        for (const gcode::Word& w : block.words) {
            if (w.isNumber()) {
                evaluated.add(w.letter, w.number, w.column);
                continue;
            }
            Value v = evaluator_.evaluate(w.value);
            if (!v.vacant) { // FANUC: an address whose value is vacant is as if not written
                evaluated.add(w.letter, v.number, w.column);
            }
        }
    }
    if (machine_.manageTools(evaluated)) {
        ++frames_[frameIndex].pc;
        return;
    }
    if (!mayCall(evaluated)) {
        sendToSink(evaluated, frameIndex);
        return;
    }
    auto& words = evaluated.words;
    auto take = [&words](auto predicate) -> std::optional<WordValue> {
        auto it = std::find_if(words.begin(), words.end(), predicate);
        if (it == words.end()) {
            return std::nullopt;
        }
        WordValue w = *it;
        words.erase(it);
        return w;
    };
    auto takeLetter = [&take](char letter) { return take([letter](const WordValue& w) { return w.letter == letter; }); };
    auto needP = [&](const WordValue& code, const char* name) {
        auto p = takeLetter('P');
        if (!p) {
            throw MacroError::of(AlarmCode::MissingAddress, message("call_needs_p", {name}), code.column);
        }
        return *p;
    };

    std::vector<Call> calls;
    std::optional<WordValue> m99;
    std::optional<WordValue> m99Label;
    std::uint32_t callColumn = block.location.column;

    if (auto g65 = take([](const WordValue& w) { return isCode(w, 'G', 65); })) {
        WordValue p = needP(*g65, "G65");
        auto l = takeLetter('L');
        Call call{programUnit(p.value, "G65", p.column), l ? std::llround(l->value) : 1, true, -1, {}};
        takeArguments(words, dialect_.callArguments, call.arguments, true);
        calls.push_back(std::move(call));
        callColumn = g65->column;
    }
    std::optional<int> homeAxis; // the dialect's built-in homing program, called by M98
    std::optional<int> libraryHomeAxis; // a library's homing program (O501), called by M98 for this axis
    if (auto m98 = take([](const WordValue& w) { return isCode(w, 'M', 98); })) {
        WordValue p = needP(*m98, "M98");
        auto l = takeLetter('L');
        const bool homing = roundToInt(p.value) == dialect_.homingProgram;
        if (homing && !program_.findUnit(dialect_.homingProgram)) {
            homeAxis = builtInHomingAxis(words, m98->column);
        } else {
            if (homing) {
                auto x = std::find_if(words.begin(), words.end(), [](const WordValue& w) { return w.letter == 'X'; });
                if (x != words.end() && wholeNumber(x->value) && x->value <= 4) {
                    libraryHomeAxis = roundToInt(x->value);
                }
            }
            Call call{programUnit(p.value, "M98", p.column), l ? std::llround(l->value) : 1,
                      dialect_.m98OpensLocalLevel, -1, {}};
            if (dialect_.m98OpensLocalLevel) {
                takeArguments(words, dialect_.callArguments, call.arguments, true);
            }
            calls.push_back(std::move(call));
        }
        callColumn = m98->column;
    }
    if ((m99 = take([](const WordValue& w) { return isCode(w, 'M', 99); }))) {
        m99Label = takeLetter('P');
    }
    if (dialect_.tCodeProgram >= 0 && !handlingCode(codeKey('T', 0))) {
        if (auto unit = tCodeUnit_) {
            if (auto t = takeLetter('T')) {
                // `T5` runs O20000 as `M98 P20000 X5` does; #1504 holds the target tool
                evaluator_.writeVariable(1504, Value::of(t->value), {}, t->column);
                Call call{*unit, 1, true, codeKey('T', 0), {}};
                if (auto x = dialect_.callArgument('X')) {
                    call.arguments.emplace_back(*x, t->value);
                }
                calls.push_back(std::move(call));
                callColumn = t->column;
            }
        }
    }
    for (std::size_t i = 0; i < words.size();) {
        const WordValue w = words[i];
        bool isM = w.letter == 'M';
        if ((!isM && w.letter != 'G') || !wholeNumber(w.value)) {
            ++i;
            continue;
        }
        int n = roundToInt(w.value);
        std::int32_t key = codeKey(w.letter, n);
        const CodeCall* configured = configuredCall(w.letter, n);
        if (configured == nullptr && !options_.callCodes.empty() && options_.callCodes.find(w.letter, n)) {
            ++i; // FANUC: inside a program a code called, the code is an ordinary one
            continue;
        }
        std::optional<std::uint32_t> unit;
        if (configured) {
            unit = programUnit(configured->program, isM ? "M code program" : "G code program", w.column);
        } else {
            unit = handlerFor(w.letter, n);
        }
        if (!unit || handlingCode(key)) {
            ++i;
            continue;
        }
        words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
        if (configured && configured->kind == CallKind::Macro) {
            // FANUC 6050-6059, 6080-6089: called as G65 calls, the block's other words its arguments
            auto l = takeLetter('L');
            Call call{*unit, l ? std::llround(l->value) : 1, true, key, {}};
            takeArguments(words, dialect_.callArguments, call.arguments, true);
            calls.push_back(std::move(call));
        } else if (configured) {
            // [codes] M6 = 9001, FANUC 6071-6079: a subprogram call, after the block's other words
            calls.push_back(Call{*unit, 1, dialect_.m98OpensLocalLevel, key, {}});
        } else {
            Call call{*unit, 1, true, key, {}}; // a handler program gets arguments
            takeArguments(words, isM ? dialect_.callArguments : dialect_.handlerArguments, call.arguments, false);
            if (!isM && cycleHandlerCall(n)) {
                prepareCycleCall(call, n, words, w.column);
            }
            calls.push_back(std::move(call));
        }
        callColumn = w.column;
    }
    if (addressLetters_ != 0) {
        takeAddressCalls(words, calls, callColumn);
    }
    if (calls.empty()) {
        if (auto repeat = repeatCycle(words, dialect_.handlerArguments)) {
            prepareCycleCall(*repeat, handlerCycle_->key & 0xFFFF, words, block.location.column);
            calls.push_back(std::move(*repeat));
        }
    }

    evaluated.reindex(); // calls and their arguments were taken out
    if (!sendToSink(evaluated, frameIndex)) {
        return;
    }
    if (homeAxis) {
        if (auto failure = machine_.builtInHoming(*homeAxis)) {
            throw MacroError::of(failure->code, failure->words, callColumn);
        }
    }
    if (libraryHomeAxis) {
        machine_.homingStarts(*libraryHomeAxis);
    }
    if (m99) {
        returnFromFrame(m99Label ? std::optional<double>(m99Label->value) : std::nullopt,
                        m99Label ? m99Label->column : m99->column, true);
        return;
    }
    for (auto it = calls.rbegin(); it != calls.rend(); ++it) {
        pushCall(*it, callColumn);
    }
}

} // namespace m350::macro
