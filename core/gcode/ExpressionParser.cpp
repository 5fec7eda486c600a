#include "core/gcode/ExpressionParser.h"

#include "core/gcode/StrayBracket.h"

#include <cmath>

namespace m350::gcode {

// `X12.5` and `X-3`, most of any real program, without the precedence chain.
bool ExpressionParser::plainNumber(Word& word) {
    bool negative = tokens_.peek().kind == TokenKind::Minus;
    bool signed_ = negative || tokens_.peek().kind == TokenKind::Plus;
    const Token& number = tokens_.peek(signed_ ? 1 : 0);
    if (number.kind != TokenKind::Number) {
        return false;
    }
    word.number = negative ? -number.number : number.number;
    word.value = kNoExpr;
    tokens_.next();
    if (signed_) {
        tokens_.next();
    }
    return true;
}

ExprId ExpressionParser::binary(BinaryOp op, ExprId lhs, ExprId rhs, std::uint32_t column) {
    ExprNode n;
    n.kind = ExprKind::Binary;
    n.op = static_cast<std::uint8_t>(op);
    n.lhs = lhs;
    n.rhs = rhs;
    n.column = column;
    return pool_.add(n);
}

std::optional<BinaryOp> ExpressionParser::comparisonAhead() {
    const Token& t = tokens_.peek();
    if (t.kind == TokenKind::Compare) {
        if (!dialect_.cStyleComparisons) {
            const char* word[] = {"EQ", "NE", "LT", "GT", "LE", "GE"};
            findings_.fail(t, message("parse_comparison_spelling",
                            {tokens_.source(t), std::string(dialect_.name),
                             word[static_cast<int>(t.compare) - static_cast<int>(BinaryOp::Eq)]}));
        }
        return t.compare;
    }
    if (t.kind == TokenKind::Keyword && t.keyword >= Keyword::Eq && t.keyword <= Keyword::Ge) {
        return static_cast<BinaryOp>(static_cast<int>(BinaryOp::Eq) + static_cast<int>(t.keyword) -
                                     static_cast<int>(Keyword::Eq));
    }
    return std::nullopt;
}

// The operator of one precedence level at the cursor: two symbols and two keywords (the FANUC
// bitwise ones, which a dialect without them refuses by name).
struct ExpressionParser::Level {
    TokenKind symbols[2];
    BinaryOp symbolOps[2];
    Keyword keywords[2];
    BinaryOp keywordOps[2];
    const char* refusals[2]; // message ids
};

std::optional<BinaryOp> ExpressionParser::operatorAhead(const Level& level) {
    const Token& t = tokens_.peek();
    if (t.kind == level.symbols[0]) {
        return level.symbolOps[0];
    }
    if (t.kind == level.symbols[1]) {
        return level.symbolOps[1];
    }
    if (t.kind != TokenKind::Keyword) { // most often: a letter, the end, a ']'
        return std::nullopt;
    }
    for (int i = 0; i < 2; ++i) {
        if (t.keyword == level.keywords[i]) {
            if (!dialect_.bitwiseKeywords) {
                findings_.fail(t, message(level.refusals[i], {std::string(keywordSpelling(t.keyword)), std::string(dialect_.name)}));
            }
            return level.keywordOps[i];
        }
    }
    return std::nullopt;
}

std::optional<BinaryOp> ExpressionParser::additiveAhead() {
    static constexpr Level kAdditive{{TokenKind::Plus, TokenKind::Minus}, {BinaryOp::Add, BinaryOp::Sub},
                                     {Keyword::Or, Keyword::Xor}, {BinaryOp::Or, BinaryOp::Xor},
                                     {"parse_no_or", "parse_no_xor"}};
    return operatorAhead(kAdditive);
}

std::optional<BinaryOp> ExpressionParser::termAhead() {
    static constexpr Level kTerm{{TokenKind::Star, TokenKind::Slash}, {BinaryOp::Mul, BinaryOp::Div},
                                 {Keyword::And, Keyword::Mod}, {BinaryOp::And, BinaryOp::Mod},
                                 {"parse_no_and", "parse_no_mod"}};
    return operatorAhead(kTerm);
}

// One precedence level: operands of the next level, joined left to right by this level's operators
// (the levels as template arguments, so that each is the loop it was when written out).
template <ExprId (ExpressionParser::*Operand)(), std::optional<BinaryOp> (ExpressionParser::*Ahead)()>
ExprId ExpressionParser::leftToRight() {
    ExprId lhs = (this->*Operand)();
    while (auto op = (this->*Ahead)()) {
        const std::uint32_t column = tokens_.next().column;
        lhs = binary(*op, lhs, (this->*Operand)(), column);
    }
    return lhs;
}

ExprId ExpressionParser::parseExpression() {
    return leftToRight<&ExpressionParser::parseAdditive, &ExpressionParser::comparisonAhead>();
}
ExprId ExpressionParser::parseAdditive() { return leftToRight<&ExpressionParser::parseTerm, &ExpressionParser::additiveAhead>(); }
ExprId ExpressionParser::parseTerm() { return leftToRight<&ExpressionParser::parseUnary, &ExpressionParser::termAhead>(); }

// Deeper nesting than any real program uses would exhaust the stack; refuse it as an error.
ExpressionParser::Nesting ExpressionParser::enterNesting(const Token& at) {
    constexpr int kMaxNesting = 64;
    if (++depth_ > kMaxNesting) {
        findings_.fail(at, message("parse_nesting", {std::to_string(kMaxNesting)}));
    }
    return Nesting{depth_};
}

ExprId ExpressionParser::parseUnary() {
    Nesting nesting = enterNesting(tokens_.peek());
    if (tokens_.peek().kind == TokenKind::Minus || tokens_.peek().kind == TokenKind::Plus) {
        const Token& sign = tokens_.next();
        ExprId operand = parseUnary();
        if (pool_[operand].kind == ExprKind::Number) {
            if (sign.kind == TokenKind::Plus) {
                return operand;
            }
            ExprNode folded = pool_[operand];
            folded.number = -folded.number;
            folded.column = sign.column;
            return pool_.add(folded);
        }
        ExprNode n;
        n.kind = ExprKind::Unary;
        n.op = static_cast<std::uint8_t>(sign.kind == TokenKind::Minus ? UnaryOp::Negate : UnaryOp::Plus);
        n.lhs = operand;
        n.column = sign.column;
        return pool_.add(n);
    }
    return parsePrimary();
}

ExprId ExpressionParser::parsePrimary() {
    const Token& t = tokens_.peek();
    switch (t.kind) {
    case TokenKind::Number: {
        tokens_.next();
        ExprNode n;
        n.kind = ExprKind::Number;
        n.number = t.number;
        n.column = t.column;
        return pool_.add(n);
    }
    case TokenKind::Hash: return parseVariable();
    case TokenKind::LBracket: return parseBracketed();
    case TokenKind::Keyword:
        if (isFunctionKeyword(t.keyword)) {
            return parseFunction();
        }
        break;
    case TokenKind::RBracket: failStrayBracket(tokens_, findings_, t, "this expression");
    default: break;
    }
    findings_.fail(t, message("parse_expected_value", {tokens_.describeWords(t)}));
}

ExprId ExpressionParser::parseBracketed() {
    const Token& open = tokens_.next();
    ExprId inner = parseExpression();
    if (tokens_.peek().kind != TokenKind::RBracket) {
        findings_.fail(tokens_.peek(), message("parse_missing_bracket", {std::to_string(open.column), tokens_.describeWords(tokens_.peek())}));
    }
    tokens_.next();
    return inner;
}

ExprId ExpressionParser::parseVariable() {
    Nesting nesting = enterNesting(tokens_.peek());
    const Token& hash = tokens_.next();
    ExprNode n;
    n.kind = ExprKind::Variable;
    n.column = hash.column;
    const Token& t = tokens_.peek();
    if (t.kind == TokenKind::Number) {
        tokens_.next();
        if (t.number != std::floor(t.number)) {
            findings_.fail(t, message("parse_variable_whole", {tokens_.source(t)}));
        }
        n.number = t.number;
    } else if (t.kind == TokenKind::LBracket) {
        n.lhs = parseBracketed();
    } else if (t.kind == TokenKind::Hash) {
        n.lhs = parseVariable();
    } else {
        findings_.fail(t, message("parse_hash_value", {tokens_.describeWords(t)}));
    }
    return pool_.add(n);
}

ExprId ExpressionParser::parseFunction() {
    const Token& name = tokens_.next();
    Function f = functionOf(name.keyword);
    bool extended = f == Function::Asin || f == Function::Acos || f == Function::Ln || f == Function::Exp ||
                    f == Function::Bin || f == Function::Bcd;
    if (extended && !dialect_.extendedFunctions) {
        findings_.fail(name, message("parse_no_function", {std::string(keywordSpelling(name.keyword)), std::string(dialect_.name)}));
    }
    if (tokens_.peek().kind != TokenKind::LBracket) {
        findings_.fail(tokens_.peek(), message("parse_function_argument", {std::string(keywordSpelling(name.keyword))}));
    }
    ExprNode n;
    n.kind = ExprKind::Function;
    n.op = static_cast<std::uint8_t>(f);
    n.column = name.column;
    const Token& open = tokens_.next();
    n.lhs = parseExpression();
    if (tokens_.peek().kind == TokenKind::Comma && f == Function::Atan && dialect_.atanComma) {
        tokens_.next();
        n.rhs = parseExpression();
    }
    if (tokens_.peek().kind != TokenKind::RBracket) {
        findings_.fail(tokens_.peek(), message("parse_missing_bracket_of", {std::string(keywordSpelling(name.keyword)),
                                                          std::to_string(open.column), tokens_.describeWords(tokens_.peek())}));
    }
    tokens_.next();
    // ATAN[a]/[b] where the dialect has it; otherwise ATAN[x] has one argument (the evaluator
    // answers it as ATAN[x]/[1])
    if (f == Function::Atan && n.rhs == kNoExpr && tokens_.peek().kind == TokenKind::Slash &&
        tokens_.peek(1).kind == TokenKind::LBracket) {
        if (!dialect_.atanSlash) {
            findings_.fail(tokens_.peek(), message("parse_atan_slash", {std::string(dialect_.name)}));
        }
        tokens_.next();
        n.rhs = parseBracketed();
    }
    return pool_.add(n);
}

} // namespace m350::gcode
