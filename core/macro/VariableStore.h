#pragma once

#include "core/params/ParameterTable.h"
#include "core/gcode/Dialect.h"
#include "core/macro/Value.h"
#include "core/macro/VariableMap.h"

#include <unordered_map>
#include <vector>

namespace m350::macro {

// Storage for the variables the macro layer owns: locals per call level, common, retained,
// plain system values, and the parameter table seen as #(N+500) on the M350.
class VariableStore {
public:
    VariableStore(const gcode::Dialect& dialect, params::ParameterTable& parameters, const VariableLayout& layout = {});

    const VariableMap& map() const { return map_; }
    const gcode::Dialect& dialect() const { return dialect_; }
    params::ParameterTable& parameters() { return parameters_; }

    void pushLocals();
    void popLocals();
    std::size_t localDepth() const { return locals_.size() / static_cast<std::size_t>(dialect_.localCount); }

    // Plain variables of the kinds this store owns (everything but the machine's kinds).
    Value read(const VariableInfo& info, int number) const;
    void write(const VariableInfo& info, int number, Value value);
    static bool ownsKind(VariableKind kind);

    // FANUC clears #1-#33 and its common variables below #500 on reset; the M350 clears its locals.
    void reset();

private:
    Value& localSlot(int number);
    const Value& localSlot(int number) const;
    Value unset() const { return dialect_.hasVacant ? Value::empty() : Value::of(0); }

    const gcode::Dialect& dialect_;
    params::ParameterTable& parameters_;
    VariableMap map_;
    std::vector<Value> locals_; // localCount values per level, innermost last
    std::vector<Value> globals_;                // numbers up to VariableMap::kMaxVariable
    std::unordered_map<int, Value> declared_;   // a machine's common variables above it (#98000 ...)
};

} // namespace m350::macro
