#pragma once

#include <cstdint>
#include <vector>

namespace m350::gcode {

using ExprId = std::int32_t;
inline constexpr ExprId kNoExpr = -1;

enum class ExprKind : std::uint8_t { Number, Variable, Unary, Binary, Function };

enum class UnaryOp : std::uint8_t { Negate, Plus };

enum class BinaryOp : std::uint8_t {
    Add, Sub, Mul, Div, Mod, And, Or, Xor, // arithmetic and FANUC bitwise
    Eq, Ne, Lt, Gt, Le, Ge                 // comparisons give 1 or 0
};

enum class Function : std::uint8_t {
    Abs, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Round, Fix, Fup, Ln, Exp, Bin, Bcd
};

// One node of an expression tree. Trees live in an ExpressionPool and refer to children by index,
// so a parsed program is a few flat vectors that execute without re-reading text.
//   Number:   `number`
//   Variable: `#number` when lhs == kNoExpr, else `#[lhs]`
//   Unary:    op (UnaryOp) applied to lhs
//   Binary:   lhs op (BinaryOp) rhs
//   Function: op (Function) of lhs, and rhs for the two-argument ATAN
struct ExprNode {
    double number = 0.0; // fields ordered by size: 24 bytes a node, a million nodes a 200k-line file
    ExprId lhs = kNoExpr;
    ExprId rhs = kNoExpr;
    std::uint32_t column = 0;
    ExprKind kind = ExprKind::Number;
    std::uint8_t op = 0;
};
static_assert(sizeof(ExprNode) == 24);

class ExpressionPool {
public:
    ExprId add(const ExprNode& node) {
        nodes_.push_back(node);
        return static_cast<ExprId>(nodes_.size() - 1);
    }
    const ExprNode& operator[](ExprId id) const { return nodes_[static_cast<std::size_t>(id)]; }
    std::size_t size() const { return nodes_.size(); }
    void reserve(std::size_t n) { nodes_.reserve(n); }

private:
    std::vector<ExprNode> nodes_;
};

bool isComparison(BinaryOp op);

} // namespace m350::gcode
