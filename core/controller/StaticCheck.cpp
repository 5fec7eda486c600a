// `m350-sim check`: what the loaded program would alarm on that is knowable without running it
// (issue 13: `check` said ok to programs that alarm on line 1). Only the main file is checked; the
// machine's libraries are the machine's. Each finding is what the run would say, at its place.
#include "core/controller/Controller.h"

#include "core/common/Numeric.h"
#include "core/interp/ModalInterpreter.h"
#include "core/macro/Evaluator.h"
#include "core/macro/MacroError.h"

#include <array>

namespace m350::controller {

namespace {

using gcode::Block;
using gcode::Control;
using gcode::ExprId;
using gcode::ExprKind;
using gcode::Word;

bool isConstant(const gcode::ExpressionPool& pool, ExprId id) {
    if (id == gcode::kNoExpr) {
        return true;
    }
    const gcode::ExprNode& node = pool[id];
    return node.kind != ExprKind::Variable && isConstant(pool, node.lhs) && isConstant(pool, node.rhs);
}

bool isWord(const Word& w, char letter, int code) {
    return w.letter == letter && w.isNumber() && w.number == code;
}

class ProgramCheck {
public:
    ProgramCheck(const gcode::Program& program, const config::MachineConfig& config, macro::Evaluator& evaluator,
                 const macro::VariableMap& variables, std::vector<gcode::Diagnostic>& out)
        : program_(program), config_(config), evaluator_(evaluator), variables_(variables), out_(out) {}

    void block(const Block& b) {
        location_ = b.location;
        for (const gcode::Assignment& a : b.assignments) {
            assignment(a);
        }
        expression(b.condition);
        expression(b.target);
        for (const Word& w : b.words) {
            expression(w.value);
        }
        if (b.control == Control::None && !b.words.empty()) {
            words(b);
        }
    }

    // A unit that calls itself (M98 P / G65 P its own number) with no IF, WHILE or GOTO that could
    // stop it nests until the call limit.
    void unit(const gcode::ProgramUnit& u) {
        if (u.number < 0) {
            return;
        }
        const Block* selfCall = nullptr;
        const Word* callWord = nullptr;
        for (std::uint32_t i = u.begin; i < u.end; ++i) {
            const Block& b = program_.blocks[i];
            if (b.control != Control::None) {
                return; // a condition or jump may end the recursion
            }
            bool calls = false;
            for (const Word& w : b.words) {
                calls |= isWord(w, 'M', 98) || isWord(w, 'G', 65);
            }
            for (const Word& w : b.words) {
                if (calls && w.letter == 'P' && w.isNumber() && w.number == u.number && !selfCall) {
                    selfCall = &b;
                    callWord = &w;
                }
            }
        }
        if (selfCall) {
            location_ = selfCall->location;
            report(callWord->column, "O" + std::to_string(u.number) +
                                         " calls itself on every pass: the calls nest until the nesting limit "
                                         "(no IF, WHILE or GOTO could stop them)");
        }
    }

private:
    void report(std::uint32_t column, std::string message) {
        out_.push_back({gcode::Severity::Error, gcode::DiagnosticKind::Syntax, program_.fileName(location_),
                        location_.line, column, std::move(message)});
    }

    // Runs `what`; a MacroError it throws is a finding.
    template <typename F> void tryEvaluate(F what) {
        try {
            what();
        } catch (const macro::MacroError& e) {
            report(e.column, e.message);
        }
    }

    // The largest constant parts of an expression are evaluated (1/0, SQRT[-1], overflow); a
    // variable whose number is constant must exist.
    void expression(ExprId id) {
        if (id == gcode::kNoExpr) {
            return;
        }
        const gcode::ExpressionPool& pool = program_.expressions;
        if (isConstant(pool, id)) {
            tryEvaluate([&] { evaluator_.evaluate(id); });
            return;
        }
        const gcode::ExprNode& node = pool[id];
        if (node.kind == ExprKind::Variable) {
            if (node.lhs == gcode::kNoExpr || isConstant(pool, node.lhs)) {
                tryEvaluate([&] { variableNumber(id); });
            } else {
                expression(node.lhs);
            }
            return;
        }
        expression(node.lhs);
        expression(node.rhs);
    }

    int variableNumber(ExprId variable) {
        int number = evaluator_.variableNumber(variable);
        if (variables_.describe(number).kind == macro::VariableKind::Undefined) {
            throw macro::MacroError{AlarmCode::UndefinedVariable,
                                    "#" + std::to_string(number) + " does not exist in the " +
                                        std::string(config_.dialect->name) + " dialect",
                                    program_.expressions[variable].column};
        }
        return number;
    }

    void assignment(const gcode::Assignment& a) {
        const gcode::ExpressionPool& pool = program_.expressions;
        expression(a.value);
        if (!isConstant(pool, pool[a.index].lhs)) {
            expression(pool[a.index].lhs);
            return;
        }
        tryEvaluate([&] {
            int number = variableNumber(a.index);
            if (variables_.describe(number).readOnly) {
                throw macro::MacroError{AlarmCode::ReadOnlyVariable,
                                        "cannot write " + variables_.describeText(number) +
                                            ": it is read-only",
                                        a.column};
            }
        });
    }

    // Whether a G or M word may hand the block to a macro (its words become arguments, which may
    // repeat: G65 P9000 I1 J2 K3 I4).
    bool mayCall(const Word& w) const {
        if (!w.isNumber()) {
            return true;
        }
        const int code = roundToInt(w.number);
        if (config_.codePrograms.count({w.letter, code}) != 0 || isWord(w, 'G', 65) ||
            isWord(w, 'M', 98) || isWord(w, 'M', 99) || isWord(w, 'G', 10) || isWord(w, 'G', 11)) {
            return true; // G10/G11: FANUC tool life entry takes its own words
        }
        const gcode::Dialect& d = *config_.dialect;
        const int base = w.letter == 'G' ? d.gHandlerBase : d.mHandlerBase;
        return base >= 0 && program_.findHandler(base + code, w.letter == 'G' ? gcode::FileRole::GLibrary
                                                                             : gcode::FileRole::MLibrary);
    }

    void words(const Block& b) {
        for (const Word& w : b.words) {
            if ((w.letter == 'G' || w.letter == 'M') && mayCall(w)) {
                return;
            }
        }
        std::array<bool, 26> seen{};
        for (const Word& w : b.words) {
            if (w.letter == 'G' && !interp::ModalInterpreter::knowsGCode(*config_.dialect, w.number)) {
                report(w.column, "G" + formatCode(w.number) + ": not a G code this machine knows");
            }
            if (w.letter == 'G' || w.letter == 'M' || w.letter < 'A' || w.letter > 'Z') {
                continue;
            }
            bool& twice = seen[static_cast<std::size_t>(w.letter - 'A')];
            if (twice) {
                report(w.column, std::string(1, w.letter) + " appears twice in one block");
            }
            twice = true;
        }
    }

    static std::string formatCode(double value) {
        std::string text = std::to_string(value);
        text.erase(text.find_last_not_of('0') + 1);
        if (!text.empty() && text.back() == '.') {
            text.pop_back();
        }
        return text;
    }

    const gcode::Program& program_;
    const config::MachineConfig& config_;
    macro::Evaluator& evaluator_;
    const macro::VariableMap& variables_;
    std::vector<gcode::Diagnostic>& out_;
    gcode::SourceLocation location_;
};

} // namespace

std::vector<gcode::Diagnostic> Controller::checkWithoutRunning() {
    std::vector<gcode::Diagnostic> findings;
    macro::Evaluator evaluator(program_.expressions, *config_.dialect, store_, *this);
    ProgramCheck check(program_, config_, evaluator, store_.map(), findings);
    for (const gcode::ProgramUnit& unit : program_.units) {
        const gcode::FileRole role = program_.files[unit.file].role;
        if (role != gcode::FileRole::Main && role != gcode::FileRole::Mdi) {
            continue;
        }
        for (std::uint32_t i = unit.begin; i < unit.end; ++i) {
            check.block(program_.blocks[i]);
        }
        check.unit(unit);
    }
    return findings;
}

} // namespace m350::controller
