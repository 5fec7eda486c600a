// The lints a trainer asked for (issue 28): mistakes that pass `check` because the program is valid,
// and then hang, leave a cylinder open or read an empty variable on the machine.
#include "core/check/TraineeLint.h"

#include "core/common/Message.h"
#include "core/common/Numeric.h"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace m350::check {

namespace {

using gcode::Block;
using gcode::BinaryOp;
using gcode::Control;
using gcode::ExprId;
using gcode::ExprKind;
using gcode::ExprNode;
using gcode::ProgramUnit;
using gcode::Word;
using macro::VariableKind;

bool isWord(const Word& w, char letter, int code) {
    return w.letter == letter && w.isNumber() && w.number == code;
}

const Word* findWord(const Block& b, char letter, int code) {
    for (const Word& w : b.words) {
        if (isWord(w, letter, code)) {
            return &w;
        }
    }
    return nullptr;
}

// The outputs of a loop or a path judged per unit: more are not judged (the lint stays linear in
// practice on generated programs).
constexpr std::size_t kMostWritesJudged = 200;

class UnitLint {
public:
    UnitLint(const gcode::Program& program, const gcode::Dialect& dialect, const macro::VariableMap& variables,
             std::vector<gcode::Diagnostic>& out)
        : program_(program), pool_(program.expressions), dialect_(dialect), variables_(variables), out_(out) {}

    void inputWaits(const ProgramUnit& u) {
        for (std::uint32_t b = u.begin; b < u.end; ++b) {
            const Block& w = program_.blocks[b];
            if (w.control != Control::While || w.condition == gcode::kNoExpr || w.partner <= static_cast<std::int32_t>(b) ||
                static_cast<std::uint32_t>(w.partner) >= u.end) {
                continue;
            }
            std::optional<ExprId> input;
            bool steady = true;
            forEachVariable(w.condition, [&](ExprId v) {
                const VariableKind kind = kindOf(v);
                if (kind == VariableKind::Input || kind == VariableKind::InterfaceInput ||
                    kind == VariableKind::InterfaceInputs) {
                    input = input ? input : v;
                } else if (kind != VariableKind::Parameter && kind != VariableKind::Local &&
                           kind != VariableKind::Common && kind != VariableKind::Retained) {
                    steady = false; // a clock or another value that changes by itself may end the wait
                }
            });
            if (input && steady && !bodyMayLeave(b + 1, static_cast<std::uint32_t>(w.partner))) {
                report(w, w.controlColumn, message("lint_input_wait", {text(*input)}));
            }
        }
    }

    // The unit a run starts with, unless something calls it (then its locals are arguments).
    void readsBeforeSet(const ProgramUnit& u) {
        std::set<int> set;
        std::set<int> said;
        for (std::uint32_t b = u.begin; b < u.end; ++b) {
            const Block& block = program_.blocks[b];
            if (block.control == Control::MGetData || sharesLocals(block)) {
                return; // sets variables the lint cannot see
            }
            auto read = [&](ExprId root) {
                forEachVariable(root, [&](ExprId v) {
                    const ExprNode& node = pool_[v];
                    if (node.lhs != gcode::kNoExpr || variables_.describe(number(node)).kind != VariableKind::Local) {
                        return;
                    }
                    const int n = number(node);
                    if (!set.contains(n) && !vacancyTest(root, v) && said.insert(n).second) {
                        report(block, node.column, message("lint_read_before_set", {std::to_string(n)}));
                    }
                });
            };
            for (const gcode::Assignment& a : block.assignments) {
                read(a.value);
                const ExprNode& target = pool_[a.index];
                if (target.lhs != gcode::kNoExpr) {
                    return; // #[...] = may set any of them
                }
                set.insert(number(target));
            }
            read(block.condition);
            read(block.target);
            for (const Word& w : block.words) {
                read(w.value);
            }
        }
    }

    void outputsLeftOn(const ProgramUnit& u) {
        std::vector<std::pair<std::uint32_t, const gcode::Assignment*>> ons;
        std::set<std::string> switchedOff;
        for (std::uint32_t b = u.begin; b < u.end; ++b) {
            for (const gcode::Assignment& a : program_.blocks[b].assignments) {
                if (outputKey(a.index).empty()) {
                    continue;
                }
                if (switchesOn(a)) {
                    ons.emplace_back(b, &a);
                } else {
                    switchedOff.insert(outputKey(a.index));
                }
            }
        }
        if (ons.size() > kMostWritesJudged) {
            ons.resize(kMostWritesJudged);
        }
        for (const auto& [b, a] : ons) {
            const std::string key = outputKey(a->index);
            if (auto end = pathLeavingOn(u, b, key, switchedOff.contains(key))) {
                report(program_.blocks[b], a->column,
                       message("lint_output_left_on", {text(a->index), end->first, std::to_string(end->second)}));
            }
        }
    }

    // M6 runs O10006, which is empty, and the community's advice is never to end right after it.
    void m30AfterM6(const ProgramUnit& u) {
        bool m6 = false;
        for (std::uint32_t b = u.begin; b < u.end; ++b) {
            const Block& block = program_.blocks[b];
            const bool here = findWord(block, 'M', 6) != nullptr;
            if (const Word* m30 = findWord(block, 'M', 30); m30 && (m6 || here) && block.control == Control::None) {
                report(block, m30->column, message("lint_m30_after_m6"));
            }
            m6 = here && block.control == Control::None;
        }
    }

private:
    static int number(const ExprNode& node) { return roundToInt(node.number); }

    template <typename F> void forEachVariable(ExprId root, F visit) const {
        if (root == gcode::kNoExpr || pool_[root].kind == ExprKind::Number) {
            return; // most words: no allocation for them
        }
        std::vector<ExprId> pending{root};
        while (!pending.empty()) {
            const ExprId id = pending.back();
            pending.pop_back();
            if (id == gcode::kNoExpr) {
                continue;
            }
            const ExprNode& node = pool_[id];
            if (node.kind == ExprKind::Variable) {
                visit(id);
            }
            if (node.kind != ExprKind::Number) {
                pending.push_back(node.rhs);
                pending.push_back(node.lhs);
            }
        }
    }

    // The number a variable's index starts from: #1520 or #[1520+#13-1] (the factory's indexing).
    std::optional<int> base(ExprId variable) const {
        const ExprNode& v = pool_[variable];
        if (v.lhs == gcode::kNoExpr) {
            return number(v);
        }
        ExprId at = v.lhs;
        while (pool_[at].kind == ExprKind::Binary &&
               (pool_[at].op == static_cast<std::uint8_t>(BinaryOp::Add) ||
                pool_[at].op == static_cast<std::uint8_t>(BinaryOp::Sub))) {
            at = pool_[at].lhs;
        }
        if (pool_[at].kind != ExprKind::Number) {
            return std::nullopt;
        }
        return number(pool_[at]);
    }

    VariableKind kindOf(ExprId variable) const {
        const std::optional<int> n = base(variable);
        return n ? variables_.describe(*n).kind : VariableKind::Local;
    }

    // `#1 EQ #0` (FANUC's "was this argument given?") reads #1 to test it for vacancy.
    bool vacancyTest(ExprId root, ExprId variable) const {
        bool test = false;
        std::vector<ExprId> pending{root};
        while (!pending.empty() && !test) {
            const ExprId id = pending.back();
            pending.pop_back();
            if (id == gcode::kNoExpr || pool_[id].kind == ExprKind::Number) {
                continue;
            }
            const ExprNode& node = pool_[id];
            auto vacant = [&](ExprId side) {
                return pool_[side].kind == ExprKind::Variable && pool_[side].lhs == gcode::kNoExpr &&
                       variables_.describe(number(pool_[side])).kind == VariableKind::Null;
            };
            if (node.kind == ExprKind::Binary && (node.op == static_cast<std::uint8_t>(BinaryOp::Eq) ||
                                                  node.op == static_cast<std::uint8_t>(BinaryOp::Ne))) {
                test = (node.lhs == variable && vacant(node.rhs)) || (node.rhs == variable && vacant(node.lhs));
            }
            pending.push_back(node.rhs);
            pending.push_back(node.lhs);
        }
        return test;
    }

    // M98 runs a subprogram on the caller's locals (FANUC); an M code a program handles may too.
    bool sharesLocals(const Block& block) const {
        for (const Word& w : block.words) {
            if (w.letter != 'M' || !w.isNumber()) {
                continue;
            }
            const std::optional<std::int32_t> handler = dialect_.handlerProgram('M', roundToInt(w.number));
            if (w.number == 98 || (handler && program_.findHandler(*handler, gcode::FileRole::MLibrary))) {
                return true;
            }
        }
        return false;
    }

    static bool calls(const Block& block) {
        for (const Word& w : block.words) {
            if (isWord(w, 'G', 65) || isWord(w, 'G', 66) || w.letter == 'T') {
                return true;
            }
        }
        return false;
    }

    // Whether a loop's body may end the wait another way: a GOTO or IF, an assignment (a counter, an
    // alarm), an M or T code (a macro, M99, M30), a call, a word that is an expression.
    bool bodyMayLeave(std::uint32_t first, std::uint32_t end) const {
        for (std::uint32_t b = first; b < end; ++b) {
            const Block& block = program_.blocks[b];
            if ((block.control != Control::None && block.control != Control::While && block.control != Control::End) ||
                !block.assignments.empty() || block.programEnd) {
                return true;
            }
            for (const Word& w : block.words) {
                if (w.letter == 'M' || w.letter == 'T' || !w.isNumber() || isWord(w, 'G', 65) || isWord(w, 'G', 66)) {
                    return true;
                }
            }
        }
        return false;
    }

    // An output written by `#index =`: its key (the index as written), empty for anything else.
    std::string outputKey(ExprId index) const {
        const VariableKind kind = kindOf(index);
        return kind == VariableKind::Output || kind == VariableKind::InterfaceOutput ? text(index) : std::string{};
    }

    bool switchesOn(const gcode::Assignment& a) const {
        return pool_[a.value].kind == ExprKind::Number && pool_[a.value].number != 0.0;
    }

    // Whether this block turns the output off or may (an expression), or stops the run (an alarm).
    bool endsOn(const Block& block, const std::string& key) const {
        if (block.control == Control::IfThen) {
            return false; // only when its condition holds
        }
        if (sharesLocals(block) || calls(block)) {
            return true; // the program it calls may switch it off (M155 clamps through slib-m.nc)
        }
        for (const gcode::Assignment& a : block.assignments) {
            const VariableKind kind = kindOf(a.index);
            if (kind == VariableKind::Alarm || kind == VariableKind::StopMessage ||
                (outputKey(a.index) == key && !switchesOn(a))) {
                return true;
            }
        }
        return false;
    }

    // A path from the block after `from` on which the output stays on until M30 (or M99, or the
    // unit's end, when the unit switches it off on other paths): the end's code and line.
    std::optional<std::pair<std::string, std::uint32_t>> pathLeavingOn(const ProgramUnit& u, std::uint32_t from,
                                                                       const std::string& key, bool managed) const {
        std::vector<bool> seen(u.end - u.begin, false);
        std::vector<std::uint32_t> pending{from + 1};
        std::uint32_t lastLine = program_.blocks[u.end - 1].location.line;
        while (!pending.empty()) {
            const std::uint32_t b = pending.back();
            pending.pop_back();
            if (b >= u.end) {
                if (managed) {
                    return std::make_pair(bilingual("the program's end", "程序结尾"), lastLine);
                }
                continue;
            }
            if (seen[b - u.begin]) {
                continue;
            }
            seen[b - u.begin] = true;
            const Block& block = program_.blocks[b];
            if (endsOn(block, key)) {
                continue;
            }
            if (block.control == Control::None) {
                for (int code : {30, 2}) {
                    if (findWord(block, 'M', code)) {
                        return std::make_pair(code == 30 ? std::string("M30") : std::string("M02"), block.location.line);
                    }
                }
                if (findWord(block, 'M', 99)) {
                    if (managed) {
                        return std::make_pair(std::string("M99"), block.location.line);
                    }
                    continue;
                }
            }
            switch (block.control) {
            case Control::Goto:
            case Control::IfGoto: {
                if (block.control == Control::IfGoto) {
                    pending.push_back(b + 1);
                }
                if (block.target != gcode::kNoExpr && pool_[block.target].kind == ExprKind::Number) {
                    if (auto to = u.labels.find(roundToInt(pool_[block.target].number), b)) {
                        pending.push_back(*to);
                    }
                }
                break;
            }
            case Control::While:
                if (block.condition != gcode::kNoExpr && block.partner >= 0) {
                    pending.push_back(static_cast<std::uint32_t>(block.partner) + 1);
                }
                pending.push_back(b + 1);
                break;
            case Control::End:
                if (block.partner >= 0) {
                    pending.push_back(static_cast<std::uint32_t>(block.partner));
                }
                break;
            default: pending.push_back(b + 1); break;
            }
        }
        return std::nullopt;
    }

    // An expression as the program writes it: #1552, #[1520+#13-1], 3.5.
    std::string text(ExprId id) const {
        const ExprNode& node = pool_[id];
        switch (node.kind) {
        case ExprKind::Number: {
            std::ostringstream s;
            s.precision(15);
            s << node.number;
            return s.str();
        }
        case ExprKind::Variable:
            return node.lhs == gcode::kNoExpr ? "#" + std::to_string(number(node)) : "#[" + text(node.lhs) + "]";
        case ExprKind::Unary: return (node.op == 0 ? "-" : "+") + text(node.lhs);
        case ExprKind::Binary: {
            static const char* const ops[] = {"+", "-", "*", "/", " MOD ", " AND ", " OR ", " XOR ",
                                              " EQ ", " NE ", " LT ", " GT ", " LE ", " GE "};
            const std::string right = pool_[node.rhs].kind == ExprKind::Binary ? "[" + text(node.rhs) + "]" : text(node.rhs);
            return text(node.lhs) + ops[node.op] + right;
        }
        case ExprKind::Function: return "[...]";
        }
        return {};
    }

    void report(const Block& block, std::uint32_t column, const Message& words) {
        out_.push_back(gcode::diagnostic(gcode::Severity::Warning, gcode::DiagnosticKind::Lint,
                                         program_.fileName(block.location), block.location.line, column, words));
    }

    const gcode::Program& program_;
    const gcode::ExpressionPool& pool_;
    const gcode::Dialect& dialect_;
    const macro::VariableMap& variables_;
    std::vector<gcode::Diagnostic>& out_;
};

// Whether a program of the file calls unit `number` (M98 P / G65 P / a code's handler): its locals are
// then its caller's or its arguments.
bool called(const gcode::Program& program, std::int32_t number) {
    for (const Block& block : program.blocks) {
        bool calls = false;
        for (const Word& w : block.words) {
            calls |= isWord(w, 'M', 98) || isWord(w, 'G', 65) || isWord(w, 'G', 66);
        }
        for (const Word& w : block.words) {
            if (calls && w.letter == 'P' && w.isNumber() && roundToInt(w.number) == number) {
                return true;
            }
        }
    }
    return false;
}

} // namespace

std::vector<gcode::Diagnostic> TraineeLint::findings(std::uint32_t file) const {
    std::vector<gcode::Diagnostic> found;
    UnitLint lint(program_, dialect_, variables_, found);
    const std::optional<std::uint32_t> main = program_.mainUnit();
    for (const ProgramUnit& u : program_.units) {
        if (u.file != file || u.begin >= u.end) {
            continue;
        }
        lint.inputWaits(u);
        lint.outputsLeftOn(u);
        if (dialect_.id == gcode::DialectId::M350) {
            lint.m30AfterM6(u);
        }
        // A program numbered as a macro (O9000 on: FANUC's macros, the M350's code handlers) is
        // called with arguments; a numbered main program that something calls is too.
        const bool runFirst = main && &program_.units[*main] == &u && (u.number < 0 || (u.number < 9000 && !called(program_, u.number)));
        if (runFirst) {
            lint.readsBeforeSet(u);
        }
    }
    std::stable_sort(found.begin(), found.end(), [](const gcode::Diagnostic& a, const gcode::Diagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
    return found;
}

} // namespace m350::check
