#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Expression.h"
#include "core/gcode/LineFindings.h"
#include "core/gcode/LineTokens.h"

#include <optional>

namespace m350::gcode {

// The expressions of a line, read from its tokens into the program's expression pool, one method
// per precedence level:
//   comparison  (== != < > <= >= EQ NE LT GT LE GE)
//   additive    (+ - OR XOR)
//   term        (* / AND MOD)
//   unary       (- +)
//   primary     (number, #var, #[expr], [expr], FUNC[...])
// What the dialect lacks (OR on the M350, ATAN[a]/[b] ...) and nesting deeper than any program
// needs fail the line (LineFindings::fail).
class ExpressionParser {
public:
    ExpressionParser(const Dialect& dialect, ExpressionPool& pool, LineTokens& tokens, LineFindings& findings)
        : dialect_(dialect), pool_(pool), tokens_(tokens), findings_(findings) {}

    // A new line: no brackets, signs or indirections open.
    void startLine() { depth_ = 0; }
    // A signed number alone (`X12.5`, `X-3`, most of any real program): kept in the word, without
    // the precedence chain; false (nothing read) otherwise.
    bool plainNumber(Word& word);
    ExprId parseExpression();
    // `#1`, `#[expr]`, `##1`: the tokens start at the '#'.
    ExprId parseVariable();
    // Sums without a comparison: an address's value where the dialect reads arithmetic unbracketed
    // (`Z10+#5`).
    ExprId parseAdditive();
    // One value with its signs: an address's value where arithmetic needs brackets, a GOTO target.
    ExprId parseUnary();

private:
    ExprId parseTerm();
    ExprId parsePrimary();
    ExprId parseFunction();
    ExprId parseBracketed();
    ExprId binary(BinaryOp op, ExprId lhs, ExprId rhs, std::uint32_t column);
    std::optional<BinaryOp> comparisonAhead();
    std::optional<BinaryOp> additiveAhead();
    std::optional<BinaryOp> termAhead();
    struct Level;
    std::optional<BinaryOp> operatorAhead(const Level& level);
    template <ExprId (ExpressionParser::*Operand)(), std::optional<BinaryOp> (ExpressionParser::*Ahead)()>
    ExprId leftToRight();

    struct Nesting {
        int& depth;
        ~Nesting() { --depth; }
    };
    [[nodiscard]] Nesting enterNesting(const Token& at);

    const Dialect& dialect_;
    ExpressionPool& pool_;
    LineTokens& tokens_;
    LineFindings& findings_;
    int depth_ = 0; // nesting of brackets, signs and indirections in the current expression
};

} // namespace m350::gcode
