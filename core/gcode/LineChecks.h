#pragma once

#include "core/gcode/Block.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Expression.h"
#include "core/gcode/LineFindings.h"
#include "core/gcode/LineTokens.h"

#include <cstddef>
#include <optional>

namespace m350::gcode {

// What the grammar alone would let through or say badly, checked on a line's tokens so that the
// message helps an operator: a number written with an exponent, a comment nested in a comment, a
// table added to instead of indexed, and a broken WHILE / END line that still opens or closes its
// loop (so the error is said once, not again as an unpaired END).
class LineChecks {
public:
    LineChecks(const Dialect& dialect, const ExpressionPool& pool, const LineTokens& tokens, LineFindings& findings)
        : dialect_(dialect), pool_(pool), tokens_(tokens), findings_(findings) {}

    // `#1=1E308`: fails the line (G-code has no exponents; the E would be read as a word).
    void checkExponents() const;
    // `(rough (T1) pass)`: a note at the inner '('.
    void lintNestedComments() const;
    // `X[#1330+#1300-1]` (the tokens from `firstToken` to `endToken` are the word's value): a lint.
    void lintTableArithmetic(const Word& word, std::size_t firstToken, std::size_t endToken) const;
    // For a line that failed: the loop block a WHILE, DO or END line still stands for, else none.
    std::optional<Block> brokenLoopBlock(Block block) const;

private:
    const Dialect& dialect_;
    const ExpressionPool& pool_;
    const LineTokens& tokens_;
    LineFindings& findings_;
};

} // namespace m350::gcode
