#include "core/macro/Evaluator.h"

#include "core/common/Numeric.h"
#include "core/macro/MacroError.h"
#include "core/macro/MessageText.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace m350::macro {

using gcode::BinaryOp;
using gcode::ExprKind;
using gcode::ExprNode;
using gcode::Function;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Bitwise operators and MOD work on integers; values beyond 2^53 have no exact integer anyway.
std::int64_t toInteger(double v) {
    constexpr double kLimit = 9.0e15;
    if (std::isnan(v)) {
        return 0;
    }
    return static_cast<std::int64_t>(std::llround(std::clamp(v, -kLimit, kLimit)));
}

std::int64_t bcdToBinary(std::int64_t bcd) {
    std::int64_t result = 0;
    std::int64_t scale = 1;
    for (; bcd > 0; bcd >>= 4, scale *= 10) {
        result += (bcd & 0xF) * scale;
    }
    return result;
}

std::int64_t binaryToBcd(std::int64_t value) {
    std::int64_t result = 0;
    for (int shift = 0; value > 0 && shift < 60; value /= 10, shift += 4) { // 15 digits fit
        result |= (value % 10) << shift;
    }
    return result;
}

} // namespace

Value Evaluator::evaluate(gcode::ExprId id) {
    const ExprNode& node = pool_[id];
    switch (node.kind) {
    case ExprKind::Number: return Value::of(node.number);
    case ExprKind::Variable: return readVariable(variableNumber(id), node.column);
    case ExprKind::Unary: {
        double v = number(node.lhs);
        return Value::of(node.op == static_cast<std::uint8_t>(gcode::UnaryOp::Negate) ? -v : v);
    }
    case ExprKind::Binary: return binaryChain(id);
    case ExprKind::Function: return finite(Value::of(function(node)), node.column);
    }
    return Value::of(0);
}

namespace {

// 99999999 or 1e+308, not std::to_string's 309 digits and six decimals.
std::string readableNumber(double n) {
    std::ostringstream text;
    text.precision(15);
    text << n;
    return text.str();
}

} // namespace

Message macroAlarmWords(double value, std::string_view text) {
    const std::string number = std::to_string(3000 + static_cast<long long>(roundToInt(value)));
    return text.empty() ? message("macro_alarm", {number}) : message("macro_alarm_text", {number, std::string(text)});
}

int Evaluator::variableNumber(gcode::ExprId variableNode) {
    const ExprNode& node = pool_[variableNode];
    double n = node.lhs == gcode::kNoExpr ? node.number : number(node.lhs);
    double rounded = std::round(n);
    if (std::abs(n - rounded) > 1e-6 || rounded < 0 || rounded > store_.map().lastNumber()) {
        throw MacroError::of(AlarmCode::UndefinedVariable,
                             message("variable_number_range", {readableNumber(n), std::to_string(store_.map().lastNumber())}),
                             node.column);
    }
    return static_cast<int>(rounded);
}

Value Evaluator::readVariable(int number, std::uint32_t column) {
    VariableInfo info = store_.map().describe(number);
    if (info.kind == VariableKind::Undefined) {
        throw MacroError::of(AlarmCode::UndefinedVariable, store_.map().undefinedWords(number), column);
    }
    return VariableStore::ownsKind(info.kind) ? store_.read(info, number) : machine_.readSystem(info, number);
}

void Evaluator::writeVariable(int number, Value value, std::string_view text, std::uint32_t column) {
    VariableInfo info = store_.map().describe(number);
    if (info.kind == VariableKind::Undefined) {
        throw MacroError::of(AlarmCode::UndefinedVariable, store_.map().undefinedWords(number), column);
    }
    if (info.readOnly) {
        throw MacroError::of(AlarmCode::ReadOnlyVariable,
                             message("variable_read_only", {store_.map().describeWords(number)}), column);
    }
    if (info.kind == VariableKind::Parameter) {
        if (auto refused = machine_.parameterWrite(info.index, value.asNumber())) {
            throw MacroError::of(AlarmCode::RightsLimited, *refused, column);
        }
    }
    if (VariableStore::ownsKind(info.kind)) {
        store_.write(info, number, value);
        return;
    }
    std::string formatted;
    if (info.kind == VariableKind::Message || info.kind == VariableKind::Dialog) {
        double values[4];
        for (int i = 0; i < 4; ++i) {
            values[i] = readVariable(kMessageValueFirst + i, column).asNumber();
        }
        formatted = formatMessageText(text, values);
    } else if (info.kind == VariableKind::Alarm) {
        formatted = expandVariableFields(text, [&](int n) -> std::optional<double> {
            Value v = readVariable(n, column);
            return v.vacant ? std::nullopt : std::optional<double>(v.number);
        });
    } else {
        formatted = std::string(text);
    }
    if (auto refused = machine_.writeSystem(info, number, value.asNumber(), formatted)) {
        const AlarmCode code = info.kind == VariableKind::Alarm ? AlarmCode::MacroAlarm : AlarmCode::InvalidArgument;
        throw MacroError::of(code, *refused, column);
    }
}

// A result that overflowed or is not a number never becomes a position, feed or time: FANUC
// alarms here too.
Value Evaluator::finite(Value value, std::uint32_t column) {
    if (!value.vacant && !std::isfinite(value.number)) {
        throw MacroError::of(AlarmCode::InvalidArgument,
                             std::isnan(value.number) ? message("result_nan") : message("result_infinite"), column);
    }
    return value;
}

// `1+1+1+...` parses into a left-deep chain as long as the line: evaluated along its left spine
// with a loop, so a chain of any length needs no deeper stack than one of its operands.
Value Evaluator::binaryChain(gcode::ExprId id) {
    const ExprNode& top = pool_[id];
    if (pool_[top.lhs].kind != ExprKind::Binary) { // no chain: the common case, no bookkeeping
        Value lhs = evaluate(top.lhs);
        return finite(binary(top, lhs, evaluate(top.rhs)), top.column);
    }
    spine_.clear();
    while (pool_[id].kind == ExprKind::Binary) {
        spine_.push_back(id);
        id = pool_[id].lhs;
    }
    std::vector<gcode::ExprId> spine;
    spine.swap(spine_); // the right operands may hold chains of their own
    Value value = evaluate(id);
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
        const ExprNode& node = pool_[*it];
        value = finite(binary(node, value, evaluate(node.rhs)), node.column);
    }
    spine.clear();
    spine_.swap(spine); // keep the capacity for the next expression
    return value;
}

Value Evaluator::binary(const ExprNode& node, Value lhs, Value rhs) {
    auto op = static_cast<BinaryOp>(node.op);
    if (op == BinaryOp::Eq || op == BinaryOp::Ne) {
        bool equal = (lhs.vacant || rhs.vacant) ? (lhs.vacant && rhs.vacant) : lhs.number == rhs.number;
        return Value::of((op == BinaryOp::Eq) == equal ? 1.0 : 0.0);
    }
    double a = lhs.asNumber();
    double b = rhs.asNumber();
    switch (op) {
    case BinaryOp::Add: return Value::of(a + b);
    case BinaryOp::Sub: return Value::of(a - b);
    case BinaryOp::Mul: return Value::of(a * b);
    case BinaryOp::Div:
        if (b == 0.0) {
            throw MacroError::of(AlarmCode::DivisionByZero, message("division_by_zero"), node.column);
        }
        return Value::of(a / b);
    case BinaryOp::Mod: {
        std::int64_t divisor = toInteger(b);
        if (divisor == 0) {
            throw MacroError::of(AlarmCode::DivisionByZero, message("mod_by_zero"), node.column);
        }
        return Value::of(divisor == -1 ? 0.0 : static_cast<double>(toInteger(a) % divisor));
    }
    case BinaryOp::And: return Value::of(static_cast<double>(toInteger(a) & toInteger(b)));
    case BinaryOp::Or: return Value::of(static_cast<double>(toInteger(a) | toInteger(b)));
    case BinaryOp::Xor: return Value::of(static_cast<double>(toInteger(a) ^ toInteger(b)));
    case BinaryOp::Lt: return Value::of(a < b ? 1.0 : 0.0);
    case BinaryOp::Gt: return Value::of(a > b ? 1.0 : 0.0);
    case BinaryOp::Le: return Value::of(a <= b ? 1.0 : 0.0);
    case BinaryOp::Ge: return Value::of(a >= b ? 1.0 : 0.0);
    default: return Value::of(0);
    }
}

double Evaluator::function(const ExprNode& node) {
    auto f = static_cast<Function>(node.op);
    double x = number(node.lhs);
    auto domain = [&](bool ok, const char* what) {
        if (!ok) {
            throw MacroError::of(AlarmCode::InvalidArgument, message("function_domain", {what, std::to_string(x)}),
                                 node.column);
        }
    };
    switch (f) {
    case Function::Abs: return std::abs(x);
    case Function::Sin: return std::sin(x * kDegree);
    case Function::Cos: return std::cos(x * kDegree);
    case Function::Tan: return std::tan(x * kDegree);
    case Function::Asin: domain(x >= -1 && x <= 1, "ASIN"); return std::asin(x) / kDegree;
    case Function::Acos: domain(x >= -1 && x <= 1, "ACOS"); return std::acos(x) / kDegree;
    case Function::Atan: {
        // One argument, ATAN[x], is ATAN[x]/[1], so it follows its dialect's rule for the two-argument
        // form. FANUC answers 0 <= angle < 360 (parameter 6004#0 NAT = 0, the default: ATAN[-1]/[-1]
        // = 225, so ATAN[-1] = 315); the M350 follows atan2's -180..180 (ATAN[-1] = -45).
        double angle = std::atan2(x, node.rhs == gcode::kNoExpr ? 1.0 : number(node.rhs)) / kDegree;
        return (dialect_.id == gcode::DialectId::Fanuc && angle < 0) ? angle + 360.0 : angle;
    }
    case Function::Sqrt: domain(x >= 0, "SQRT"); return std::sqrt(x);
    case Function::Round: return std::round(x); // half away from zero
    case Function::Fix: return std::trunc(x);
    case Function::Fup: return x >= 0 ? std::ceil(x) : std::floor(x);
    case Function::Ln: domain(x > 0, "LN"); return std::log(x);
    case Function::Exp: return std::exp(x);
    case Function::Bin: return static_cast<double>(bcdToBinary(toInteger(x)));
    case Function::Bcd: return static_cast<double>(binaryToBcd(toInteger(x)));
    }
    return 0.0;
}

} // namespace m350::macro
