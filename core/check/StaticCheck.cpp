// `m350-sim check`: what the loaded program would alarm on that is knowable without running it
// (issue 13: `check` said ok to programs that alarm on line 1). Only the main file is checked; the
// machine's libraries are the machine's. Each finding is what the run would say, at its place.
#include "core/check/StaticCheck.h"

#include "core/common/EchoText.h"
#include "core/common/Numeric.h"
#include "core/gcode/DiagnosticCap.h"
#include "core/interp/ModalInterpreter.h"
#include "core/macro/Evaluator.h"
#include "core/macro/MachineAccess.h"
#include "core/macro/MacroError.h"
#include "core/macro/VariableStore.h"
#include "core/params/ParameterTable.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <optional>
#include <sstream>
#include <unordered_set>
#include <utility>
#include <vector>

namespace m350::check {

namespace {

using gcode::Block;
using gcode::Control;
using gcode::ExprId;
using gcode::ExprKind;
using gcode::Word;

// The parts of one expression that read no variable, found bottom-up once with an explicit stack:
// a generated sum of 100,000 terms is one chain as deep as it is long, and asking each node of it
// again would take quadratic time.
class ConstantParts {
public:
    ConstantParts(const gcode::ExpressionPool& pool, ExprId root) {
        std::vector<std::pair<ExprId, bool>> stack; // a node, and whether its operands are done
        if (root != gcode::kNoExpr) {
            stack.emplace_back(root, false);
        }
        while (!stack.empty()) {
            auto [id, operandsDone] = stack.back();
            stack.pop_back();
            const gcode::ExprNode& node = pool[id];
            if (!operandsDone) {
                stack.emplace_back(id, true);
                for (ExprId operand : {node.rhs, node.lhs}) {
                    if (operand != gcode::kNoExpr) {
                        stack.emplace_back(operand, false);
                    }
                }
                continue;
            }
            if (node.kind == ExprKind::Variable || !constant(node.lhs) || !constant(node.rhs)) {
                readsVariable_.insert(id);
            }
        }
    }
    bool constant(ExprId id) const { return id == gcode::kNoExpr || !readsVariable_.contains(id); }

private:
    std::unordered_set<ExprId> readsVariable_;
};

bool isWord(const Word& w, char letter, int code) {
    return w.letter == letter && w.isNumber() && w.number == code;
}

// The check evaluates constants only (a variable's number, 1/0), which read no variable: the
// variables and the machine it evaluates against are empty ones.
class NoMachine final : public macro::MachineAccess {
public:
    macro::Value readSystem(const macro::VariableInfo&, int) override { return macro::Value::empty(); }
    std::optional<Message> writeSystem(const macro::VariableInfo&, int, double, std::string_view) override {
        return message("check_writes_no_variable");
    }
};

class ProgramCheck {
public:
    ProgramCheck(const gcode::Program& program, const gcode::Dialect& dialect, const macro::CallCodes& callCodes,
                 const interp::ModalInterpreter::CoordinateFeatures& coordinates, macro::Evaluator& evaluator,
                 const macro::VariableMap& variables, std::vector<gcode::Diagnostic>& out)
        : program_(program), dialect_(dialect), callCodes_(callCodes), coordinates_(coordinates),
          evaluator_(evaluator), variables_(variables), out_(out) {}

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

    // Units that call one another (or themselves) on every pass, before any IF, WHILE, GOTO or
    // program end could stop them, nest until the call limit. Reported at the call in `u`.
    void callCycle(std::uint32_t unitIndex) {
        auto call = firstCall(program_.units[unitIndex]);
        std::vector<std::int32_t> chain{program_.units[unitIndex].number};
        for (auto next = call; next; next = firstCall(program_.units[*program_.findUnit(next->callee)])) {
            if (next->callee == chain.front()) {
                for (std::int32_t other : chain) {
                    std::uint32_t index = *program_.findUnit(other);
                    if (index < unitIndex && checked(program_.units[index])) {
                        return; // reported once, at the cycle's first unit in the checked file
                    }
                }
                location_ = call->block->location;
                report(call->word->column, cycleText(chain));
                return;
            }
            if (std::find(chain.begin(), chain.end(), next->callee) != chain.end() || chain.size() > 64) {
                return; // a cycle that does not pass through this unit: reported at its own units
            }
            chain.push_back(next->callee);
        }
    }

    // The files `check` looks at: the program (or MDI lines), not the machine's libraries.
    bool checked(const gcode::ProgramUnit& u) const {
        const gcode::FileRole role = program_.files[u.file].role;
        return role == gcode::FileRole::Main || role == gcode::FileRole::Mdi;
    }

private:
    struct Call {
        std::int32_t callee = 0;
        const Block* block = nullptr;
        const Word* word = nullptr;
    };

    // The call a unit makes on every pass: the first M98 P / G65 P of a constant program that
    // exists, when no control statement or M99 / M30 / M02 comes before it.
    std::optional<Call> firstCall(const gcode::ProgramUnit& u) const {
        if (u.number < 0) {
            return std::nullopt;
        }
        for (std::uint32_t i = u.begin; i < u.end; ++i) {
            const Block& b = program_.blocks[i];
            if (b.control != Control::None) {
                return std::nullopt;
            }
            bool calls = false;
            bool ends = false;
            for (const Word& w : b.words) {
                calls |= isWord(w, 'M', 98) || isWord(w, 'G', 65);
                ends |= isWord(w, 'M', 99) || isWord(w, 'M', 30) || isWord(w, 'M', 2);
                if (w.letter == 'L' && w.isNumber() && w.number == 0) {
                    return std::nullopt; // L0: called no times
                }
            }
            for (const Word& w : b.words) {
                if (calls && w.letter == 'P' && w.isNumber() && program_.findUnit(roundToInt(w.number))) {
                    return Call{roundToInt(w.number), &b, &w};
                }
            }
            if (ends) {
                return std::nullopt;
            }
        }
        return std::nullopt;
    }

    static Message cycleText(const std::vector<std::int32_t>& chain) {
        if (chain.size() == 1) {
            return message("lint_calls_itself", {std::to_string(chain.front())});
        }
        std::string path;
        for (std::int32_t n : chain) {
            path += "O" + std::to_string(n) + " -> ";
        }
        return message("lint_calls_itself_through", {std::to_string(chain.front()), path});
    }

    // A finding repeats the program's own text (a code, a chain of program numbers, an evaluator's
    // message about a constant): cut as every echo is.
    void report(std::uint32_t column, std::string message) {
        out_.push_back({gcode::Severity::Error, gcode::DiagnosticKind::Syntax, program_.fileName(location_),
                        location_.line, column, clipEcho(std::move(message))});
    }

    void report(std::uint32_t column, const Message& words) {
        out_.push_back(gcode::diagnostic(gcode::Severity::Error, gcode::DiagnosticKind::Syntax,
                                         program_.fileName(location_), location_.line, column, words));
    }

    // Runs `what`; a MacroError it throws is a finding.
    template <typename F> void tryEvaluate(F what) {
        try {
            what();
        } catch (const macro::MacroError& e) {
            if (e.messageId.empty()) {
                report(e.column, e.message);
            } else {
                report(e.column, Message{e.messageId, e.messageArguments});
            }
        }
    }

    // The largest constant parts of an expression are evaluated (1/0, SQRT[-1], overflow); a
    // variable whose number is constant must exist.
    void expression(ExprId id) {
        const gcode::ExpressionPool& pool = program_.expressions;
        const ConstantParts parts(pool, id);
        std::vector<ExprId> pending{id}; // depth first, the left operand first, without recursion
        while (!pending.empty()) {
            const ExprId next = pending.back();
            pending.pop_back();
            if (next == gcode::kNoExpr) {
                continue;
            }
            if (parts.constant(next)) {
                tryEvaluate([&] { evaluator_.evaluate(next); });
                continue;
            }
            const gcode::ExprNode& node = pool[next];
            if (node.kind == ExprKind::Variable) {
                if (parts.constant(node.lhs)) {
                    tryEvaluate([&] { variableNumber(next); });
                } else {
                    pending.push_back(node.lhs);
                }
                continue;
            }
            pending.push_back(node.rhs);
            pending.push_back(node.lhs);
        }
    }

    int variableNumber(ExprId variable) {
        int number = evaluator_.variableNumber(variable);
        if (variables_.describe(number).kind == macro::VariableKind::Undefined) {
            throw macro::MacroError::of(AlarmCode::UndefinedVariable, variables_.undefinedWords(number),
                                        program_.expressions[variable].column);
        }
        return number;
    }

    void assignment(const gcode::Assignment& a) {
        const gcode::ExpressionPool& pool = program_.expressions;
        expression(a.value);
        if (!ConstantParts(pool, pool[a.index].lhs).constant(pool[a.index].lhs)) {
            expression(pool[a.index].lhs);
            return;
        }
        tryEvaluate([&] {
            int number = variableNumber(a.index);
            if (variables_.describe(number).readOnly) {
                throw macro::MacroError::of(AlarmCode::ReadOnlyVariable,
                                            message("variable_read_only", {variables_.describeWords(number)}), a.column);
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
        if (callCodes_.find(w.letter, code) != nullptr || isWord(w, 'G', 65) ||
            isWord(w, 'M', 98) || isWord(w, 'M', 99) || isWord(w, 'G', 10) || isWord(w, 'G', 11)) {
            return true; // G10/G11: FANUC tool life entry takes its own words
        }
        const std::optional<std::int32_t> handler = dialect_.handlerProgram(w.letter, code);
        return handler && program_.findHandler(*handler, w.letter == 'G' ? gcode::FileRole::GLibrary
                                                                         : gcode::FileRole::MLibrary);
    }

    void words(const Block& b) {
        for (const Word& w : b.words) {
            if (((w.letter == 'G' || w.letter == 'M') && mayCall(w)) || callCodes_.address(w.letter) != nullptr) {
                return;
            }
        }
        std::array<bool, 26> seen{};
        for (const Word& w : b.words) {
            if (w.letter == 'G' && !interp::ModalInterpreter::knowsGCode(dialect_, coordinates_, w.number)) {
                report(w.column, message("unknown_g_code", {formatCode(w.number)}));
            } else if (w.letter == 'G' && std::abs(w.number - 54.1) < 1e-6) {
                additionalSystem(b);
            }
            if (w.letter == 'M' && w.isNumber() && std::abs(w.number - std::round(w.number)) < 1e-9 &&
                std::abs(w.number) < 1e9 && !interp::ModalInterpreter::knowsMCode(dialect_, roundToInt(w.number))) {
                report(w.column, interp::ModalInterpreter::unknownMCodeWords(dialect_, roundToInt(w.number),
                                                                             "M" + formatCode(w.number)));
            }
            if (w.letter == 'G' || w.letter == 'M' || w.letter < 'A' || w.letter > 'Z') {
                continue;
            }
            bool& twice = seen[static_cast<std::size_t>(w.letter - 'A')];
            if (twice) {
                report(w.column, message("word_twice", {std::string(1, w.letter)}));
            }
            twice = true;
        }
    }

    // G54.1 P<constant> beyond the machine's systems, as the run would refuse it.
    void additionalSystem(const Block& b) {
        for (const Word& p : b.words) {
            if (p.letter == 'P' && p.isNumber() &&
                (p.number != std::round(p.number) || p.number < 1 || p.number > coordinates_.additionalSystems)) {
                report(p.column, message("g54_1_range", {formatCode(p.number), std::to_string(coordinates_.additionalSystems)}));
            }
        }
    }

    // 80.1 or 1e+300 (a code of 300 digits), not std::to_string's digits and six decimals.
    static std::string formatCode(double value) {
        std::ostringstream text;
        text.precision(15);
        text << value;
        return text.str();
    }

    const gcode::Program& program_;
    const gcode::Dialect& dialect_;
    const macro::CallCodes& callCodes_;
    const interp::ModalInterpreter::CoordinateFeatures& coordinates_;
    macro::Evaluator& evaluator_;
    const macro::VariableMap& variables_;
    std::vector<gcode::Diagnostic>& out_;
    gcode::SourceLocation location_;
};

} // namespace

StaticCheck::Options StaticCheck::dialectOptions(const gcode::Dialect& dialect) {
    Options options;
    const bool fanuc = dialect.id == gcode::DialectId::Fanuc;
    options.coordinates = {options.variables.workSystems(dialect), fanuc};
    return options;
}

std::vector<gcode::Diagnostic> StaticCheck::findings() const {
    std::vector<gcode::Diagnostic> findings;
    params::ParameterTable parameters;
    macro::VariableStore variables(dialect_, parameters, options_.variables);
    NoMachine machine;
    macro::Evaluator evaluator(program_.expressions, dialect_, variables, machine);
    ProgramCheck check(program_, dialect_, callCodes_, options_.coordinates, evaluator, variables.map(), findings);
    gcode::DiagnosticCap cap; // a million lines of `#1=1/0` list the first and the last findings
    for (const gcode::ProgramUnit& unit : program_.units) {
        if (!check.checked(unit)) {
            continue;
        }
        for (std::uint32_t i = unit.begin; i < unit.end; ++i) {
            cap.trimIfLarge(findings, program_);
            check.block(program_.blocks[i]);
        }
        check.callCycle(static_cast<std::uint32_t>(&unit - program_.units.data()));
    }
    cap.finish(findings, program_, gcode::DiagnosticCap::Order::AsFiled);
    return findings;
}

} // namespace m350::check
