#include "core/macro/VariableStore.h"

namespace m350::macro {

VariableStore::VariableStore(const gcode::Dialect& dialect, params::ParameterTable& parameters,
                             const VariableLayout& layout)
    : dialect_(dialect), parameters_(parameters), map_(dialect, layout),
      globals_(VariableMap::kMaxVariable + 1, dialect.hasVacant ? Value::empty() : Value::of(0)) {
    pushLocals();
}

void VariableStore::pushLocals() {
    locals_.resize(locals_.size() + static_cast<std::size_t>(dialect_.localCount),
                   dialect_.hasVacant ? Value::empty() : Value::of(0));
}

void VariableStore::popLocals() {
    if (localDepth() > 1) {
        locals_.resize(locals_.size() - static_cast<std::size_t>(dialect_.localCount));
    }
}

bool VariableStore::ownsKind(VariableKind kind) {
    switch (kind) {
    case VariableKind::Null:
    case VariableKind::Local:
    case VariableKind::Common:
    case VariableKind::Retained:
    case VariableKind::Parameter:
    case VariableKind::System: return true;
    default: return false;
    }
}

Value& VariableStore::localSlot(int number) {
    std::size_t base = locals_.size() - static_cast<std::size_t>(dialect_.localCount);
    return locals_[base + static_cast<std::size_t>(number - dialect_.localFirst)];
}

const Value& VariableStore::localSlot(int number) const {
    std::size_t base = locals_.size() - static_cast<std::size_t>(dialect_.localCount);
    return locals_[base + static_cast<std::size_t>(number - dialect_.localFirst)];
}

Value VariableStore::read(const VariableInfo& info, int number) const {
    switch (info.kind) {
    case VariableKind::Null: return Value::empty();
    case VariableKind::Local: return localSlot(number);
    case VariableKind::Parameter: return Value::of(parameters_.get(info.index));
    default:
        if (number > VariableMap::kMaxVariable) {
            auto it = declared_.find(number);
            return it == declared_.end() ? unset() : it->second;
        }
        return globals_[static_cast<std::size_t>(number)];
    }
}

void VariableStore::write(const VariableInfo& info, int number, Value value) {
    switch (info.kind) {
    case VariableKind::Local: localSlot(number) = value; break;
    case VariableKind::Parameter: parameters_.set(info.index, value.asNumber()); break;
    default:
        if (number > VariableMap::kMaxVariable) {
            declared_[number] = value;
        } else {
            globals_[static_cast<std::size_t>(number)] = value;
        }
        break;
    }
}

void VariableStore::reset() {
    locals_.clear();
    pushLocals();
    if (!dialect_.hasVacant) {
        return;
    }
    for (const VariableRange& r : map_.rangesOf(VariableKind::Common)) {
        for (int n = r.first; n <= r.last; ++n) {
            write({VariableKind::Common, false, 0}, n, Value::empty());
        }
    }
}

} // namespace m350::macro
