#include "core/gcode/BlockParser.h"
#include "core/common/Numeric.h"

#include "core/gcode/Lexer.h"
#include "core/gcode/PlainBlockParser.h"

#include <cmath>

namespace m350::gcode {

BlockParser::BlockParser(const Dialect& dialect, ExpressionPool& pool, WordArena& words,
                         std::vector<Diagnostic>& diagnostics, std::string fileName, std::uint32_t fileIndex)
    : dialect_(dialect), pool_(pool), words_(words), diagnostics_(diagnostics), fileName_(std::move(fileName)),
      fileIndex_(fileIndex) {}

std::optional<Block> BlockParser::parse(std::string_view line, std::uint32_t lineNumber) {
    if (plainPath_) {
        Block plain;
        switch (parsePlainBlock(line, dialect_, {fileIndex_, lineNumber, 0}, pool_, words_, plain)) {
        case PlainResult::Parsed: return plain;
        case PlainResult::Empty: return std::nullopt;
        case PlainResult::Declined: break;
        }
    }
    line_ = line;
    lineNumber_ = lineNumber;
    Lexer(dialect_).tokenize(line, tokens_);
    const Token end = tokens_.back();
    tokens_.insert(tokens_.end(), kLookahead, end);
    pos_ = 0;
    depth_ = 0;
    lastLint_.clear();
    Block block;
    block.location = {fileIndex_, lineNumber, tokens_.front().column};
    try {
        parseStatement(block);
    } catch (const Failure&) {
        return brokenLoopBlock(block);
    }
    block.suspect = !lastLint_.empty();
    bool empty = block.label < 0 && block.programNumber < 0 && block.control == Control::None &&
                 block.assignments.empty() && block.words.empty();
    if (empty) {
        return std::nullopt;
    }
    return block;
}

// A WHILE or END line with a syntax error still opens or closes its loop, so the error is
// reported once and not again as an unpaired END. The program cannot run with it anyway.
std::optional<Block> BlockParser::brokenLoopBlock(Block block) const {
    std::size_t first = 0;
    while (first < tokens_.size() && (tokens_[first].kind == TokenKind::Comment ||
                                      tokens_[first].kind == TokenKind::Letter ||
                                      tokens_[first].kind == TokenKind::Number)) {
        ++first; // N label
    }
    if (first >= tokens_.size() || tokens_[first].kind != TokenKind::Keyword ||
        (tokens_[first].keyword != Keyword::While && tokens_[first].keyword != Keyword::End)) {
        return std::nullopt;
    }
    bool isWhile = tokens_[first].keyword == Keyword::While;
    block.control = isWhile ? Control::While : Control::End;
    block.controlColumn = tokens_[first].column;
    block.words = {};
    block.assignments.clear();
    block.loopId = kUnknownLoop; // the parser then trusts no pairing in this program
    for (std::size_t i = first; i + 1 < tokens_.size(); ++i) {
        bool marker = isWhile ? (tokens_[i].kind == TokenKind::Keyword && tokens_[i].keyword == Keyword::Do)
                              : i == first;
        if (marker && tokens_[i + 1].kind == TokenKind::Number) {
            block.loopId = saturatingInt(tokens_[i + 1].number);
            break;
        }
    }
    return block;
}

// The token list ends with kLookahead End tokens (see parse()), so peeking never runs past it and
// next() never moves beyond the first End.
const Token& BlockParser::peek(std::size_t ahead) const {
    return tokens_[pos_ + ahead];
}

const Token& BlockParser::next() {
    const Token& t = tokens_[pos_];
    pos_ += t.kind != TokenKind::End ? 1 : 0;
    return t;
}

bool BlockParser::atKeyword(Keyword k) const {
    return peek().kind == TokenKind::Keyword && peek().keyword == k;
}

void BlockParser::fail(const Token& at, std::string message) {
    fail(at.column, std::move(message));
}

void BlockParser::fail(std::uint32_t column, std::string message) {
    diagnostics_.push_back({Severity::Error, DiagnosticKind::Syntax, fileName_, lineNumber_, column, std::move(message)});
    throw Failure{};
}

void BlockParser::lint(std::uint32_t column, std::string message) {
    lastLint_ = message;
    diagnostics_.push_back({Severity::Error, DiagnosticKind::Lint, fileName_, lineNumber_, column, std::move(message)});
}

std::string BlockParser::source(const Token& token) const {
    return std::string(line_.substr(token.offset, token.length));
}

std::string BlockParser::describe(const Token& token) const {
    switch (token.kind) {
    case TokenKind::End: return "the end of the line";
    case TokenKind::Comment: return "a comment";
    default: return "'" + source(token) + "'";
    }
}

void BlockParser::parseStatement(Block& block) {
    for (const Token& t : tokens_) {
        if (t.issue != TokenIssue::None) {
            fail(t, Lexer(dialect_).issueMessage(t, line_));
        }
        if (t.kind == TokenKind::Comment && block.comment.empty()) {
            block.comment = std::string(commentText(t, line_));
        }
    }
    auto skipComments = [&] {
        while (peek().kind == TokenKind::Comment) {
            next();
        }
    };
    skipComments();
    if (peek().kind == TokenKind::Percent) {
        next();
        skipComments();
        if (peek().kind != TokenKind::End) {
            fail(peek(), "nothing may follow '%' on its line");
        }
        return;
    }
    if (peek().kind == TokenKind::Slash) {
        next();
        block.blockDelete = true;
    }
    if (peek().kind == TokenKind::Letter && peek().letter == 'O') {
        const Token& o = next();
        if (peek().kind != TokenKind::Number || peek().number != std::floor(peek().number)) {
            fail(o, "O must be followed by a whole program number, e.g. O20000");
        }
        block.programNumber = saturatingInt(next().number);
        skipComments();
        if (peek().kind != TokenKind::End) {
            fail(peek(), "unexpected " + describe(peek()) + " after the program number O" +
                             std::to_string(block.programNumber));
        }
        return;
    }
    if (peek().kind == TokenKind::Letter && peek().letter == 'N' && peek(1).kind == TokenKind::Number) {
        next();
        const Token& n = next();
        if (n.number != std::floor(n.number)) {
            fail(n, "a sequence number must be a whole number");
        }
        block.label = saturatingInt(n.number);
    }
    skipComments();
    if (peek().kind == TokenKind::Keyword) {
        const Token& k = peek();
        block.controlColumn = k.column;
        switch (k.keyword) {
        case Keyword::If: next(); parseIf(block); return;
        case Keyword::While: next(); parseWhile(block); return;
        case Keyword::Goto:
            next();
            block.control = Control::Goto;
            block.target = parseUnary();
            break;
        case Keyword::End:
            next();
            block.control = Control::End;
            block.loopId = parseLoopId("END");
            break;
        case Keyword::Do: fail(k, "DO without WHILE: write WHILE [condition] DO" + std::to_string(1));
        default: break;
        }
        if (block.control != Control::None) {
            skipComments();
            if (peek().kind != TokenKind::End) {
                fail(peek(), "unexpected " + describe(peek()) + " after " + std::string(keywordSpelling(k.keyword)));
            }
            return;
        }
    }
    parseItems(block);
}

ExprId BlockParser::parseCondition(const char* statement) {
    if (!dialect_.unbracketedConditions && peek().kind != TokenKind::LBracket) {
        fail(peek(), std::string("the ") + statement + " condition must be in brackets: " + statement + " [...]");
    }
    return parseExpression();
}

void BlockParser::failStrayBracket(const Token& at, const char* context) {
    std::size_t stray = pos_;
    std::size_t open = 0;
    for (std::size_t i = 0; i + 1 < stray; ++i) {
        if (tokens_[i].kind == TokenKind::LBracket && tokens_[i + 1].kind == TokenKind::Hash) {
            open = i + 1;
            break;
        }
        if (tokens_[i].kind == TokenKind::Hash && tokens_[i + 1].kind == TokenKind::Number) {
            open = i;
            break;
        }
    }
    std::string hint = hashBracketHint(open, stray);
    fail(at, std::string("unbalanced ']' in ") + context + (hint.empty() ? "" : " (did you mean " + hint + "?)"));
}

// For `#1552+#20-1]` or `[#1520+#13-1] NE 0]`: the indirect reference the author most likely meant,
// `#[1552+#20-1]`, built from the text between the '#' and the first ']' after it.
std::string BlockParser::hashBracketHint(std::size_t hashToken, std::size_t strayToken) const {
    if (hashToken + 1 >= tokens_.size() || tokens_[hashToken].kind != TokenKind::Hash ||
        tokens_[hashToken + 1].kind == TokenKind::LBracket) {
        return {}; // no hint when the reference is already written #[...]
    }
    std::size_t close = hashToken;
    while (close < strayToken && tokens_[close].kind != TokenKind::RBracket) {
        ++close;
    }
    std::uint32_t from = tokens_[hashToken].offset + 1;
    std::uint32_t to = tokens_[close].offset;
    if (to <= from) {
        return {};
    }
    return "#[" + std::string(line_.substr(from, to - from)) + "]";
}

void BlockParser::parseIf(Block& block) {
    block.condition = parseCondition("IF");
    if (peek().kind == TokenKind::RBracket) {
        failStrayBracket(peek(), "IF condition");
    }
    if (atKeyword(Keyword::Goto)) {
        next();
        block.control = Control::IfGoto;
        block.target = parseUnary();
    } else if (atKeyword(Keyword::Then)) {
        next();
        block.control = Control::IfThen;
        if (peek().kind != TokenKind::Hash) {
            fail(peek(), "THEN must be followed by an assignment such as #1 = 0, found " + describe(peek()));
        }
        block.assignments.push_back(parseAssignment());
    } else {
        fail(peek(), "IF condition must be followed by GOTOn or THEN, found " + describe(peek()));
    }
    while (peek().kind == TokenKind::Comment) {
        next();
    }
    if (peek().kind != TokenKind::End) {
        fail(peek(), "unexpected " + describe(peek()) + " after the IF statement");
    }
}

void BlockParser::parseWhile(Block& block) {
    block.control = Control::While;
    block.condition = parseCondition("WHILE");
    if (peek().kind == TokenKind::RBracket) {
        failStrayBracket(peek(), "WHILE condition");
    }
    if (!atKeyword(Keyword::Do)) {
        fail(peek(), "WHILE condition must be followed by DOm, found " + describe(peek()));
    }
    next();
    block.loopId = parseLoopId("DO");
    while (peek().kind == TokenKind::Comment) {
        next();
    }
    if (peek().kind != TokenKind::End) {
        fail(peek(), "unexpected " + describe(peek()) + " after WHILE ... DO" + std::to_string(block.loopId));
    }
}

int BlockParser::parseLoopId(const char* keyword) {
    const Token& t = peek();
    if (t.kind != TokenKind::Number || t.number != std::floor(t.number)) {
        fail(t, std::string(keyword) + " must be followed by a loop number 1-" + std::to_string(dialect_.maxLoopId) +
                    ", found " + describe(t));
    }
    next();
    int id = saturatingInt(t.number);
    if (id < 1 || id > dialect_.maxLoopId) {
        fail(t, std::string(keyword) + std::to_string(id) + ": loop numbers run from 1 to " +
                    std::to_string(dialect_.maxLoopId) + " in the " + std::string(dialect_.name) + " dialect");
    }
    return id;
}

void BlockParser::parseItems(Block& block) {
    std::size_t letters = 0;
    for (std::size_t i = pos_; i < tokens_.size(); ++i) {
        letters += tokens_[i].kind == TokenKind::Letter ? 1 : 0;
    }
    std::span<Word> room = words_.allocate(letters);
    std::size_t count = 0;
    while (peek().kind != TokenKind::End) {
        const Token& t = peek();
        switch (t.kind) {
        case TokenKind::Comment: next(); break;
        case TokenKind::Hash: block.assignments.push_back(parseAssignment()); break;
        case TokenKind::Letter: {
            std::size_t first = pos_;
            Word w = parseWord();
            lintTableArithmetic(w, first, pos_);
            if (w.letter == 'M' && pool_[w.value].kind == ExprKind::Number &&
                (pool_[w.value].number == 30 || pool_[w.value].number == 2)) {
                block.programEnd = true;
            }
            room[count++] = w;
            block.words = room.first(count);
            break;
        }
        case TokenKind::RBracket: failStrayBracket(t, "this block");
        case TokenKind::Keyword:
            fail(t, std::string(keywordSpelling(t.keyword)) + " must start the block (after the N number)");
        default: fail(t, "unexpected " + describe(t) + ": expected an address word such as G1 or X10");
        }
    }
}

Assignment BlockParser::parseAssignment() {
    Assignment a;
    a.column = peek().column;
    std::size_t hashToken = pos_;
    a.index = parseVariable();
    if (peek().kind != TokenKind::Assign) {
        for (std::size_t i = pos_; i < tokens_.size() && tokens_[i].kind != TokenKind::Assign; ++i) {
            if (tokens_[i].kind == TokenKind::RBracket) {
                pos_ = i;
                std::string hint = hashBracketHint(hashToken, i);
                fail(tokens_[i], "unbalanced ']' in the variable being assigned" +
                                     (hint.empty() ? std::string() : " (did you mean " + hint + "?)"));
            }
        }
        fail(peek(), "expected '=' after the variable, found " + describe(peek()));
    }
    next();
    if (peek().kind == TokenKind::End || peek().kind == TokenKind::Comment) {
        fail(peek(), "expected a value after '=', found " + describe(peek()));
    }
    a.value = parseExpression();
    if (peek().kind == TokenKind::Comment) {
        a.text = std::string(commentText(next(), line_));
        a.hasText = true;
    }
    if (peek().kind == TokenKind::RBracket) {
        failStrayBracket(peek(), "this assignment");
    }
    return a;
}

Word BlockParser::parseWord() {
    const Token& letter = next();
    Word w;
    w.letter = letter.letter;
    w.column = letter.column;
    TokenKind k = peek().kind;
    if (k != TokenKind::Number && k != TokenKind::Hash && k != TokenKind::LBracket && k != TokenKind::Minus &&
        k != TokenKind::Plus) {
        fail(letter, std::string("address ") + letter.letter + " needs a value, found " + describe(peek()));
    }
    w.value = plainNumber();
    if (w.value == kNoExpr) {
        w.value = parseUnary();
    }
    if (peek().kind == TokenKind::Plus || peek().kind == TokenKind::Minus || peek().kind == TokenKind::Star ||
        (peek().kind == TokenKind::Slash)) {
        fail(peek(), "arithmetic in an address value needs brackets: " + std::string(1, letter.letter) + "[...]");
    }
    return w;
}

// `X[#1330+#1300-1]` adds a pocket coordinate to a tool number: never what anyone means, and exactly
// what the M350 manual's damaged listing reads. The author wanted `X#[1330+#1300-1]`.
void BlockParser::lintTableArithmetic(const Word& word, std::size_t firstToken, std::size_t endToken) {
    const ExprNode& root = pool_[word.value];
    if (root.kind != ExprKind::Binary || dialect_.indexedTables.empty()) {
        return;
    }
    ExprId leftmost = word.value;
    while (pool_[leftmost].kind == ExprKind::Binary) {
        leftmost = pool_[leftmost].lhs;
    }
    const ExprNode& base = pool_[leftmost];
    if (base.kind != ExprKind::Variable || base.lhs != kNoExpr) {
        return;
    }
    for (const IndexedTable& table : dialect_.indexedTables) {
        if (base.number == table.base) {
            std::uint32_t from = tokens_[firstToken].offset;
            std::uint32_t to = tokens_[endToken - 1].offset + tokens_[endToken - 1].length;
            std::string written(line_.substr(from, to - from));
            std::string meant = written;
            if (auto at = meant.find("[#"); at != std::string::npos) {
                meant.replace(at, 2, "#[");
            }
            std::string b = std::to_string(table.base);
            lint(word.column, written + " adds the value of #" + b + " instead of indexing " +
                                  std::string(table.what) + " (did you mean " + meant + "?)");
            return;
        }
    }
}

// `X12.5` and `X-3`, most of any real program, without the precedence chain.
ExprId BlockParser::plainNumber() {
    bool negative = peek().kind == TokenKind::Minus;
    const Token& number = peek(negative ? 1 : 0);
    if (number.kind != TokenKind::Number) {
        return kNoExpr;
    }
    ExprNode n;
    n.kind = ExprKind::Number;
    n.number = negative ? -number.number : number.number;
    n.column = peek().column;
    next();
    if (negative) {
        next();
    }
    return pool_.add(n);
}

ExprId BlockParser::binary(BinaryOp op, ExprId lhs, ExprId rhs, std::uint32_t column) {
    ExprNode n;
    n.kind = ExprKind::Binary;
    n.op = static_cast<std::uint8_t>(op);
    n.lhs = lhs;
    n.rhs = rhs;
    n.column = column;
    return pool_.add(n);
}

std::optional<BinaryOp> BlockParser::comparisonAhead() {
    const Token& t = peek();
    if (t.kind == TokenKind::Compare) {
        if (!dialect_.cStyleComparisons) {
            const char* word[] = {"EQ", "NE", "LT", "GT", "LE", "GE"};
            fail(t, "'" + source(t) + "' is not " + std::string(dialect_.name) +
                                                        " syntax: write " +
                                                        word[static_cast<int>(t.compare) - static_cast<int>(BinaryOp::Eq)]);
        }
        return t.compare;
    }
    if (t.kind == TokenKind::Keyword && t.keyword >= Keyword::Eq && t.keyword <= Keyword::Ge) {
        return static_cast<BinaryOp>(static_cast<int>(BinaryOp::Eq) + static_cast<int>(t.keyword) -
                                     static_cast<int>(Keyword::Eq));
    }
    return std::nullopt;
}

std::optional<BinaryOp> BlockParser::additiveAhead() {
    const Token& t = peek();
    if (t.kind == TokenKind::Plus) {
        return BinaryOp::Add;
    }
    if (t.kind == TokenKind::Minus) {
        return BinaryOp::Sub;
    }
    if (t.kind == TokenKind::Keyword && (t.keyword == Keyword::Or || t.keyword == Keyword::Xor)) {
        if (!dialect_.bitwiseKeywords) {
            fail(t, std::string(keywordSpelling(t.keyword)) + " is not an " + std::string(dialect_.name) +
                        " operator" +
                        (t.keyword == Keyword::Or ? ": write OR as [a]+[b]"
                                                  : ": write XOR of two conditions as [[a]+[b]]==1"));
        }
        return t.keyword == Keyword::Or ? BinaryOp::Or : BinaryOp::Xor;
    }
    return std::nullopt;
}

std::optional<BinaryOp> BlockParser::termAhead() {
    const Token& t = peek();
    if (t.kind == TokenKind::Star) {
        return BinaryOp::Mul;
    }
    if (t.kind == TokenKind::Slash) {
        return BinaryOp::Div;
    }
    if (t.kind == TokenKind::Keyword && (t.keyword == Keyword::And || t.keyword == Keyword::Mod)) {
        if (!dialect_.bitwiseKeywords) {
            fail(t, std::string(keywordSpelling(t.keyword)) + " is not an " + std::string(dialect_.name) +
                        " operator" +
                        (t.keyword == Keyword::And ? ": write AND as [a]*[b]"
                                                   : ": write a MOD b as [a-FIX[a/b]*b]"));
        }
        return t.keyword == Keyword::And ? BinaryOp::And : BinaryOp::Mod;
    }
    return std::nullopt;
}

ExprId BlockParser::parseExpression() {
    ExprId lhs = parseAdditive();
    while (auto op = comparisonAhead()) {
        std::uint32_t column = next().column;
        lhs = binary(*op, lhs, parseAdditive(), column);
    }
    return lhs;
}

ExprId BlockParser::parseAdditive() {
    ExprId lhs = parseTerm();
    while (auto op = additiveAhead()) {
        std::uint32_t column = next().column;
        lhs = binary(*op, lhs, parseTerm(), column);
    }
    return lhs;
}

ExprId BlockParser::parseTerm() {
    ExprId lhs = parseUnary();
    while (auto op = termAhead()) {
        std::uint32_t column = next().column;
        lhs = binary(*op, lhs, parseUnary(), column);
    }
    return lhs;
}

// Deeper nesting than any real program uses would exhaust the stack; refuse it as an error.
BlockParser::Nesting BlockParser::enterNesting(const Token& at) {
    constexpr int kMaxNesting = 64;
    if (++depth_ > kMaxNesting) {
        fail(at, "expression nested more than " + std::to_string(kMaxNesting) + " levels deep");
    }
    return Nesting{depth_};
}

ExprId BlockParser::parseUnary() {
    Nesting nesting = enterNesting(peek());
    if (peek().kind == TokenKind::Minus || peek().kind == TokenKind::Plus) {
        const Token& sign = next();
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

ExprId BlockParser::parsePrimary() {
    const Token& t = peek();
    switch (t.kind) {
    case TokenKind::Number: {
        next();
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
    case TokenKind::RBracket: failStrayBracket(t, "this expression");
    default: break;
    }
    fail(t, "expected a value (a number, #variable or [expression]), found " + describe(t));
}

ExprId BlockParser::parseBracketed() {
    const Token& open = next();
    ExprId inner = parseExpression();
    if (peek().kind != TokenKind::RBracket) {
        fail(peek(), "missing ']' to close the '[' at column " + std::to_string(open.column) + ", found " +
                         describe(peek()));
    }
    next();
    return inner;
}

ExprId BlockParser::parseVariable() {
    Nesting nesting = enterNesting(peek());
    const Token& hash = next();
    ExprNode n;
    n.kind = ExprKind::Variable;
    n.column = hash.column;
    const Token& t = peek();
    if (t.kind == TokenKind::Number) {
        next();
        if (t.number != std::floor(t.number)) {
            fail(t, "variable numbers are whole numbers: #" + source(t) + " (did you mean #[...]?)");
        }
        n.number = t.number;
    } else if (t.kind == TokenKind::LBracket) {
        n.lhs = parseBracketed();
    } else if (t.kind == TokenKind::Hash) {
        n.lhs = parseVariable();
    } else {
        fail(t, "'#' must be followed by a variable number or [expression], found " + describe(t));
    }
    return pool_.add(n);
}

ExprId BlockParser::parseFunction() {
    const Token& name = next();
    Function f = functionOf(name.keyword);
    bool extended = f == Function::Asin || f == Function::Acos || f == Function::Ln || f == Function::Exp ||
                    f == Function::Bin || f == Function::Bcd;
    if (extended && !dialect_.extendedFunctions) {
        fail(name, std::string(keywordSpelling(name.keyword)) + " is not a function of the " +
                       std::string(dialect_.name) + " dialect");
    }
    if (peek().kind != TokenKind::LBracket) {
        fail(peek(), std::string(keywordSpelling(name.keyword)) + " must be followed by [argument]");
    }
    ExprNode n;
    n.kind = ExprKind::Function;
    n.op = static_cast<std::uint8_t>(f);
    n.column = name.column;
    const Token& open = next();
    n.lhs = parseExpression();
    if (peek().kind == TokenKind::Comma && f == Function::Atan && dialect_.atanComma) {
        next();
        n.rhs = parseExpression();
    }
    if (peek().kind != TokenKind::RBracket) {
        fail(peek(), "missing ']' to close " + std::string(keywordSpelling(name.keyword)) + "[ at column " +
                         std::to_string(open.column) + ", found " + describe(peek()));
    }
    next();
    if (f == Function::Atan && n.rhs == kNoExpr) {
        if (dialect_.atanSlash && peek().kind == TokenKind::Slash && peek(1).kind == TokenKind::LBracket) {
            next();
            n.rhs = parseBracketed();
        } else {
            fail(name, std::string("ATAN takes two arguments: ") +
                           (dialect_.atanSlash ? "ATAN[a]/[b]" : "ATAN[y,x]"));
        }
    }
    return pool_.add(n);
}

} // namespace m350::gcode
