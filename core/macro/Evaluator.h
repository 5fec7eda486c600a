#pragma once

#include "core/common/Message.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Expression.h"
#include "core/macro/MachineAccess.h"
#include "core/macro/Value.h"
#include "core/macro/VariableStore.h"

#include <string_view>
#include <vector>

namespace m350::macro {

// Evaluates expression trees against the variables. FANUC's vacant rules: arithmetic and
// GE/GT/LE/LT treat vacant as 0, EQ/NE tell vacant from 0, a plain `#1` keeps vacant.
// Angles are in degrees. Errors throw MacroError with the column of the offending node.
class Evaluator {
public:
    Evaluator(const gcode::ExpressionPool& pool, const gcode::Dialect& dialect, VariableStore& store,
              MachineAccess& machine)
        : pool_(pool), dialect_(dialect), store_(store), machine_(machine) {}

    Value evaluate(gcode::ExprId id);
    double number(gcode::ExprId id) { return evaluate(id).asNumber(); }
    bool condition(gcode::ExprId id) { return number(id) != 0.0; }

    // The variable number an index expression names (`#[1552+#20-1]`), checked to exist.
    int variableNumber(gcode::ExprId variableNode);

    Value readVariable(int number, std::uint32_t column);
    void writeVariable(int number, Value value, std::string_view text, std::uint32_t column);

private:
    static Value finite(Value value, std::uint32_t column);
    Value binaryChain(gcode::ExprId id);
    Value binary(const gcode::ExprNode& node, Value lhs, Value rhs);
    double function(const gcode::ExprNode& node);

    const gcode::ExpressionPool& pool_;
    const gcode::Dialect& dialect_;
    VariableStore& store_;
    MachineAccess& machine_;
    std::vector<gcode::ExprId> spine_; // binaryChain's scratch, kept for its capacity
};

// What #3000 = n (text) raises: "macro alarm 3000+n: text", the same words for the controller that
// refuses the write and the evaluator that turns it into the alarm.
Message macroAlarmWords(double value, std::string_view text);

} // namespace m350::macro
