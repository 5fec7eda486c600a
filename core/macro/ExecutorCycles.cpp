// Canned cycles handled by programs (the M350's O9073, O9081 ... in slib-g.nc): the executor keeps
// the cycle modal as the firmware does. It calls the handler for the G81 block and again for every
// later block that gives a new hole (X Y) or level (Z R), until G80 or G00-G03; the addresses keep
// their values from block to block. Each call receives, beside the block's addresses (X#0 Y#1 Z#2
// R#10 Q#14 P#13 F#16 K#9 on the M350):
//   X, Y  the hole in work coordinates, the current position for an axis the block leaves out
//   K     1 when not given
//   #30   the Z to return to: the initial level (G98) or R (G99)
//   #31   the Z the tool stands at when the call begins
//   #32   1 on the cycle's first block, 0 on the blocks that repeat it
// Handlers take absolute values: a cycle under G91 raises an alarm.
#include "core/macro/Executor.h"
#include "core/common/Numeric.h"

#include <algorithm>
#include <cmath>

namespace m350::macro {

namespace {

constexpr int kReturnLevel = 30;
constexpr int kCurrentLevel = 31;
constexpr int kFirstBlock = 32;

bool isCycleCode(int code) {
    return code == 73 || code == 74 || code == 76 || (code >= 81 && code <= 89);
}

bool hasG(const std::vector<WordValue>& words, int code) {
    return std::any_of(words.begin(), words.end(), [code](const WordValue& w) {
        return w.letter == 'G' && std::abs(w.value - code) < 1e-9;
    });
}

std::string codeName(int code) {
    return "G" + std::to_string(code);
}

} // namespace

bool Executor::cycleHandlerCall(int code) const {
    return isCycleCode(code);
}

void Executor::prepareCycleCall(Call& call, int code, const std::vector<WordValue>& blockWords, std::uint32_t column) {
    BlockSink::CycleContext context = sink_.cycleContext();
    const bool incremental = hasG(blockWords, 91) || (context.incremental && !hasG(blockWords, 90));
    const bool returnToR = hasG(blockWords, 99) || (context.returnToR && !hasG(blockWords, 98));
    const std::string name = codeName(code);
    const std::string handler = "O" + std::to_string(dialect_.gHandlerBase + code);
    if (incremental) {
        throw MacroError::of(AlarmCode::InvalidWord, message("cycle_handler_absolute", {name, handler}), column);
    }
    auto local = [this](char letter) { return dialect_.handlerArgument(letter); };
    std::map<int, double> args;
    if (handlerCycle_) {
        args = handlerCycle_->arguments; // the addresses of the cycle's earlier blocks
    }
    for (auto [variable, value] : call.arguments) {
        args[variable] = value;
    }
    for (int axis = 0; axis < 2; ++axis) { // X, Y: where the hole is, the current position if not given
        if (auto x = local(axis == 0 ? 'X' : 'Y')) {
            bool given = std::any_of(call.arguments.begin(), call.arguments.end(),
                                     [&](const auto& a) { return a.first == *x; });
            if (!given) {
                args[*x] = context.work[static_cast<std::size_t>(axis)];
            }
        }
    }
    auto z = local('Z');
    auto r = local('R');
    if (!z || !r || !args.count(*z) || !args.count(*r)) {
        throw MacroError::of(AlarmCode::MissingAddress, message("cycle_needs_z_r", {name}), column);
    }
    if (auto k = local('K'); k && !std::any_of(call.arguments.begin(), call.arguments.end(),
                                               [&](const auto& a) { return a.first == *k; })) {
        args[*k] = 1;
    }
    const bool first = !handlerCycle_;
    double initial = handlerCycle_ ? handlerCycle_->initialLevel : context.work[2];
    handlerCycle_ = HandlerCycle{call.handledCode, call.unit, args, initial};
    args[kReturnLevel] = returnToR ? args[*r] : initial;
    args[kCurrentLevel] = context.work[2];
    args[kFirstBlock] = first ? 1 : 0;
    call.arguments.assign(args.begin(), args.end());
}

std::optional<Executor::Call> Executor::repeatCycle(std::vector<WordValue>& words,
                                                    const std::array<std::int8_t, 26>& map) {
    if (!handlerCycle_ || handlingCode(handlerCycle_->key)) {
        return std::nullopt;
    }
    for (int code : {0, 1, 2, 3, 80}) {
        if (hasG(words, code)) {
            handlerCycle_.reset(); // the cycle ends; the block runs as it is
            return std::nullopt;
        }
    }
    bool newHole = std::any_of(words.begin(), words.end(), [](const WordValue& w) {
        return w.letter == 'X' || w.letter == 'Y' || w.letter == 'Z' || w.letter == 'R';
    });
    if (!newHole) {
        return std::nullopt;
    }
    Call call{handlerCycle_->unit, 1, true, handlerCycle_->key, {}};
    takeArguments(words, map, call.arguments, false);
    return call;
}

} // namespace m350::macro
