#include "core/gcode/BlockParser.h"
#include "core/common/EchoText.h"
#include "core/common/Numeric.h"

#include "core/gcode/Lexer.h"
#include "core/gcode/PlainBlockParser.h"
#include "core/gcode/StrayBracket.h"

#include <cmath>
#include <memory>

namespace m350::gcode {

BlockParser::BlockParser(const Dialect& dialect, BlockStorage& storage, std::vector<Diagnostic>& diagnostics,
                         std::string fileName, std::uint32_t fileIndex)
    : dialect_(dialect), storage_(storage), pool_(storage.expressions), findings_(diagnostics, std::move(fileName)),
      fileIndex_(fileIndex), expressions_(dialect, storage.expressions, tokens_, findings_),
      statements_(dialect, storage, tokens_, findings_, expressions_),
      checks_(dialect, storage.expressions, tokens_, findings_) {}

bool BlockParser::parse(std::string_view line, std::uint32_t lineNumber, Block& out, LineEnd lineEnd) {
    if (plainPath_ && !comment_.open) {
        switch (parsePlainBlock(line, dialect_, {fileIndex_, lineNumber, 0}, storage_, out, lineEnd)) {
        case PlainResult::Parsed: return true;
        case PlainResult::Empty: return false;
        case PlainResult::Declined: break;
        }
    }
    std::optional<Block> block = parseGeneral(line, lineNumber);
    if (block) {
        std::construct_at(&out, *block);
    }
    return block.has_value();
}

std::optional<Block> BlockParser::parse(std::string_view line, std::uint32_t lineNumber) {
    Block block;
    if (parse(line, lineNumber, block)) {
        return block;
    }
    return std::nullopt;
}

namespace {

// The longest program line read: a longer one is refused at its line, unread, so a line's tokens,
// words and echoes stay bounded (a 100 MB line took 4-6 GB). 4096 times LinuxCNC's LINELEN (255)
// and far beyond any CAM output, which keeps to a few hundred bytes (README, m350-sim). The plain
// path never sees such a line: it declines lines above kLongestPlainLine.
constexpr std::size_t kMostLineBytes = std::size_t{1024} * 1024;

} // namespace

std::optional<Block> BlockParser::parseGeneral(std::string_view line, std::uint32_t lineNumber) {
    findings_.startLine(lineNumber);
    if (line.size() > kMostLineBytes) {
        findings_.refuse(1, "the line is " + std::to_string(line.size()) + " bytes long, more than the " +
                                std::to_string(kMostLineBytes) + " a program line may have: not read");
        return std::nullopt;
    }
    tokens_.read(Lexer(dialect_), line, comment_);
    if (comment_.openedOnThisLine) {
        commentStart_ = {fileIndex_, lineNumber, comment_.column};
    }
    expressions_.startLine();
    assignments_.clear();
    checks_.lintNestedComments();
    Block block;
    block.location = {fileIndex_, lineNumber, tokens_[0].column};
    try {
        parseStatement(block);
    } catch (const LineFindings::Failure&) {
        return checks_.brokenLoopBlock(block);
    }
    block.suspect = findings_.linted();
    bool empty = block.label < 0 && block.programNumber < 0 && block.control == Control::None &&
                 assignments_.empty() && block.words.empty();
    if (empty) {
        return std::nullopt;
    }
    block.assignments = storage_.assignments.copy(assignments_);
    return block;
}

void BlockParser::parseStatement(Block& block) {
    for (const Token& t : tokens_) {
        if (t.kind == TokenKind::Keyword && (t.keyword == Keyword::Dprnt || t.keyword == Keyword::Bprnt)) {
            break; // its text is read from the line itself (StatementParser), not as tokens
        }
        if (isNote(t.issue)) {
            findings_.note(t.column, Lexer(dialect_).issueWords(t, tokens_.line()));
        } else if (t.issue != TokenIssue::None) {
            findings_.fail(t, Lexer(dialect_).issueWords(t, tokens_.line()));
        }
        if (t.kind == TokenKind::Comment && t.issue == TokenIssue::None && block.comment.empty()) {
            block.comment = storage_.text.store(commentText(t, tokens_.line()));
        }
    }
    checks_.checkExponents();
    auto skipComments = [&] {
        while (tokens_.peek().kind == TokenKind::Comment) {
            tokens_.next();
        }
    };
    skipComments();
    if (tokens_.peek().kind == TokenKind::Percent) {
        tokens_.next();
        skipComments();
        if (tokens_.peek().kind != TokenKind::End) {
            findings_.fail(tokens_.peek(), message("parse_after_percent"));
        }
        return;
    }
    if (tokens_.peek().kind == TokenKind::Slash) {
        tokens_.next();
        block.blockDelete = true;
    }
    if (tokens_.peek().kind == TokenKind::Letter && tokens_.peek().letter == 'O') {
        const Token& o = tokens_.next();
        if (tokens_.peek().kind != TokenKind::Number || tokens_.peek().number != std::floor(tokens_.peek().number)) {
            findings_.fail(o, message("parse_o_number"));
        }
        if (tokens_.peek().number > kMaxLabel) { // would be rounded into another program's number
            findings_.fail(tokens_.peek(), message("parse_o_range", {tokens_.source(tokens_.peek()), std::to_string(kMaxLabel)}));
        }
        block.programNumber = static_cast<std::int32_t>(tokens_.next().number);
        skipComments();
        if (tokens_.peek().kind != TokenKind::End) {
            findings_.fail(tokens_.peek(), message("parse_after_o", {tokens_.describeWords(tokens_.peek()), std::to_string(block.programNumber)}));
        }
        return;
    }
    if (tokens_.peek().kind == TokenKind::Letter && tokens_.peek().letter == 'N' && tokens_.peek(1).kind == TokenKind::Number) {
        tokens_.next();
        block.label = labelNumber(tokens_.next(), "N");
    }
    skipComments();
    if (tokens_.peek().kind == TokenKind::Keyword) {
        const Token& k = tokens_.peek();
        block.controlColumn = k.column;
        switch (k.keyword) {
        case Keyword::If: tokens_.next(); parseIf(block); return;
        case Keyword::Popen:
        case Keyword::Pclos:
        case Keyword::Dprnt:
        case Keyword::Bprnt:
        case Keyword::MSetData:
        case Keyword::MGetData:
        case Keyword::MByte2Data:
        case Keyword::MData2Byte: tokens_.next(); statements_.parse(block, k); return;
        case Keyword::While: tokens_.next(); parseWhile(block); return;
        case Keyword::Goto:
            tokens_.next();
            block.control = Control::Goto;
            block.target = parseGotoTarget();
            break;
        case Keyword::End:
            tokens_.next();
            block.control = Control::End;
            block.loopId = parseLoopId("END");
            break;
        case Keyword::Do:
            // `DOm ... ENDm` without WHILE: an endless loop, left by a GOTO (or stopped by the
            // runaway guard)
            tokens_.next();
            block.control = Control::While;
            block.loopId = parseLoopId("DO");
            break;
        default: break;
        }
        if (block.control != Control::None) {
            skipComments();
            if (tokens_.peek().kind != TokenKind::End) {
                findings_.fail(tokens_.peek(), message("parse_unexpected_after", {tokens_.describeWords(tokens_.peek()), std::string(keywordSpelling(k.keyword))}));
            }
            return;
        }
    }
    parseItems(block);
}

ExprId BlockParser::parseCondition(const char* statement) {
    if (!dialect_.unbracketedConditions && tokens_.peek().kind != TokenKind::LBracket) {
        findings_.fail(tokens_.peek(), message("parse_condition_brackets", {statement}));
    }
    return expressions_.parseExpression();
}

void BlockParser::parseIf(Block& block) {
    block.condition = parseCondition("IF");
    if (tokens_.peek().kind == TokenKind::RBracket) {
        failStrayBracket(tokens_, findings_, tokens_.peek(), "IF condition");
    }
    if (tokens_.atKeyword(Keyword::Goto)) {
        tokens_.next();
        block.control = Control::IfGoto;
        block.target = parseGotoTarget();
    } else if (tokens_.atKeyword(Keyword::Then)) {
        tokens_.next();
        block.control = Control::IfThen;
        if (tokens_.peek().kind != TokenKind::Hash) {
            findings_.fail(tokens_.peek(), message("parse_then_assignment", {tokens_.describeWords(tokens_.peek())}));
        }
        assignments_.push_back(parseAssignment());
    } else {
        findings_.fail(tokens_.peek(), message("parse_if_goto_then", {tokens_.describeWords(tokens_.peek())}));
    }
    while (tokens_.peek().kind == TokenKind::Comment) {
        tokens_.next();
    }
    if (tokens_.peek().kind != TokenKind::End) {
        findings_.fail(tokens_.peek(), message("parse_after_if", {tokens_.describeWords(tokens_.peek())}));
    }
}

void BlockParser::parseWhile(Block& block) {
    block.control = Control::While;
    block.condition = parseCondition("WHILE");
    if (tokens_.peek().kind == TokenKind::RBracket) {
        failStrayBracket(tokens_, findings_, tokens_.peek(), "WHILE condition");
    }
    if (!tokens_.atKeyword(Keyword::Do)) {
        findings_.fail(tokens_.peek(), message("parse_while_do", {tokens_.describeWords(tokens_.peek())}));
    }
    tokens_.next();
    block.loopId = parseLoopId("DO");
    while (tokens_.peek().kind == TokenKind::Comment) {
        tokens_.next();
    }
    if (tokens_.peek().kind != TokenKind::End) {
        findings_.fail(tokens_.peek(), message("parse_after_while", {tokens_.describeWords(tokens_.peek()), std::to_string(block.loopId)}));
    }
}

// Labels are exact: N and GOTO numbers beyond kMaxLabel are refused rather than rounded into
// another label.
std::int32_t BlockParser::labelNumber(const Token& number, const char* what) {
    if (number.number != std::floor(number.number)) {
        findings_.fail(number, message("parse_n_whole"));
    }
    if (number.number > kMaxLabel) {
        findings_.fail(number, message("parse_n_range", {what + tokens_.source(number), std::to_string(kMaxLabel)}));
    }
    return static_cast<std::int32_t>(number.number);
}

ExprId BlockParser::parseGotoTarget() {
    const Token& first = tokens_.peek();
    ExprId target = expressions_.parseUnary();
    const ExprNode& value = pool_[target];
    if (value.kind == ExprKind::Number && (value.number < 0 || value.number > kMaxLabel)) {
        const Token& last = tokens_[tokens_.position() - 1];
        findings_.fail(first, message("parse_n_range", {"GOTO" + std::string(tokens_.line().substr(first.offset, last.offset + last.length - first.offset)),
                                             std::to_string(kMaxLabel)}));
    }
    return target;
}

int BlockParser::parseLoopId(const char* keyword) {
    const Token& t = tokens_.peek();
    if (t.kind != TokenKind::Number || t.number != std::floor(t.number)) {
        findings_.fail(t, message("parse_loop_number", {keyword, std::to_string(dialect_.maxLoopId), tokens_.describeWords(t)}));
    }
    tokens_.next();
    int id = saturatingInt(t.number);
    if (id < 1 || id > dialect_.maxLoopId) {
        findings_.fail(t, message("parse_loop_range", {std::string(keyword) + std::to_string(id), std::to_string(dialect_.maxLoopId),
                                      std::string(dialect_.name)}));
    }
    return id;
}

void BlockParser::parseItems(Block& block) {
    std::size_t letters = 0;
    for (std::size_t i = tokens_.position(); i < tokens_.size(); ++i) {
        letters += tokens_[i].kind == TokenKind::Letter ? 1 : 0;
    }
    std::span<Word> room = storage_.words.allocate(letters);
    std::size_t count = 0;
    while (tokens_.peek().kind != TokenKind::End) {
        const Token& t = tokens_.peek();
        switch (t.kind) {
        case TokenKind::Comment: tokens_.next(); break;
        case TokenKind::Hash: assignments_.push_back(parseAssignment()); break;
        case TokenKind::Letter: {
            std::size_t first = tokens_.position();
            Word w = parseWord();
            checks_.lintTableArithmetic(w, first, tokens_.position());
            if (w.letter == 'M' && w.isNumber() && (w.number == 30 || w.number == 2)) {
                block.programEnd = true;
            }
            room[count++] = w;
            block.words = room.first(count);
            break;
        }
        case TokenKind::RBracket: failStrayBracket(tokens_, findings_, t, "this block");
        case TokenKind::Keyword:
            findings_.fail(t, message("parse_keyword_first", {std::string(keywordSpelling(t.keyword))}));
        default: findings_.fail(t, message("parse_expected_word", {tokens_.describeWords(t)}));
        }
    }
}

Assignment BlockParser::parseAssignment() {
    Assignment a;
    a.column = tokens_.peek().column;
    std::size_t hashToken = tokens_.position();
    a.index = expressions_.parseVariable();
    if (tokens_.peek().kind != TokenKind::Assign) {
        for (std::size_t i = tokens_.position(); i < tokens_.size() && tokens_[i].kind != TokenKind::Assign; ++i) {
            if (tokens_[i].kind == TokenKind::RBracket) {
                tokens_.moveTo(i);
                std::string hint = hashBracketHint(tokens_, hashToken, i);
                findings_.fail(tokens_[i], hint.empty() ? message("parse_bracket_assigned")
                                             : message("parse_bracket_assigned_hint", {hint}));
            }
        }
        findings_.fail(tokens_.peek(), message("parse_expected_assign", {tokens_.describeWords(tokens_.peek())}));
    }
    tokens_.next();
    if (tokens_.peek().kind == TokenKind::End || tokens_.peek().kind == TokenKind::Comment) {
        findings_.fail(tokens_.peek(), message("parse_expected_assigned_value", {tokens_.describeWords(tokens_.peek())}));
    }
    a.value = expressions_.parseExpression();
    if (tokens_.peek().kind == TokenKind::Comment) {
        a.text = storage_.text.store(commentText(tokens_.next(), tokens_.line()));
        a.hasText = true;
    }
    if (tokens_.peek().kind == TokenKind::RBracket) {
        failStrayBracket(tokens_, findings_, tokens_.peek(), "this assignment");
    }
    return a;
}

Word BlockParser::parseWord() {
    const Token& letter = tokens_.next();
    Word w;
    w.letter = letter.letter;
    w.column = wordColumn(letter.column);
    TokenKind k = tokens_.peek().kind;
    if (k != TokenKind::Number && k != TokenKind::Hash && k != TokenKind::LBracket && k != TokenKind::Minus &&
        k != TokenKind::Plus) {
        findings_.fail(letter, message("parse_address_value", {std::string(1, letter.letter), tokens_.describeWords(tokens_.peek())}));
    }
    auto arithmeticAhead = [this] {
        TokenKind k = tokens_.peek().kind;
        return k == TokenKind::Plus || k == TokenKind::Minus || k == TokenKind::Star || k == TokenKind::Slash;
    };
    const std::size_t valueStart = tokens_.position();
    if (!expressions_.plainNumber(w)) {
        w.value = dialect_.unbracketedAddressValues ? expressions_.parseAdditive() : expressions_.parseUnary();
    } else if (dialect_.unbracketedAddressValues && arithmeticAhead()) {
        tokens_.moveTo(valueStart); // `Z10+#5`: the value runs up to the next address letter
        w.value = expressions_.parseAdditive();
    }
    if (arithmeticAhead()) {
        findings_.fail(tokens_.peek(), message("parse_address_arithmetic", {std::string(1, letter.letter)}));
    }
    return w;
}

} // namespace m350::gcode
