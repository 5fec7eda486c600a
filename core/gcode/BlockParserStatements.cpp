// BlockParser: the statements that talk to devices beside the CNC. FANUC's external output (POPEN,
// DPRNT[...], BPRNT[...], PCLOS) and the M350's Modbus statements (MSETDATA[...], MGETDATA[...],
// MBYTE2DATA[...], MDATA2BYTE[...]). A DPRNT's text is no G-code (`DPRNT[TOOL*LENGTH#100[53]]`), so
// it is read from the line's characters; the Modbus arguments are expressions.
#include "core/gcode/BlockParser.h"
#include "core/gcode/ModbusStatement.h"

#include <algorithm>

namespace m350::gcode {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// What DPRNT and BPRNT send as text: FANUC's letters, digits and a few signs; `*` stands for a space.
bool isPrintText(char c) {
    static constexpr std::string_view kSigns = "*+-/.,:=?!$&@<>'\"";
    return (c >= 'A' && c <= 'Z') || isDigit(c) || kSigns.find(c) != std::string_view::npos;
}

constexpr int kMaxPrintDigits = 8; // FANUC: c + d <= 8

} // namespace

// Columns count characters: comments before the statement may hold multi-byte ones.
std::uint32_t BlockParser::columnAt(std::size_t offset) const {
    offset = std::min(offset, line_.size());
    if (offset < columnCacheOffset_) {
        columnCacheOffset_ = 0;
        columnCacheColumn_ = 1;
    }
    for (std::size_t i = columnCacheOffset_; i < offset; ++i) {
        columnCacheColumn_ += (static_cast<unsigned char>(line_[i]) & 0xC0) != 0x80 ? 1 : 0;
    }
    columnCacheOffset_ = offset;
    return columnCacheColumn_;
}

std::uint32_t BlockParser::storeStatement(const std::vector<StatementItem>& items) {
    storage_.statements.push_back(storage_.statementItems.copy(items));
    return static_cast<std::uint32_t>(storage_.statements.size() - 1);
}

void BlockParser::parseDeviceStatement(Block& block, const Token& keyword) {
    const std::string name = keywordSpelling(keyword.keyword);
    const bool output = keyword.keyword >= Keyword::Popen && keyword.keyword <= Keyword::Bprnt;
    if (output && !dialect_.externalOutput) {
        fail(keyword, name + " is FANUC's external output: the " + std::string(dialect_.name) +
                          " dialect has no POPEN, DPRNT, BPRNT or PCLOS");
    }
    if (!output && !dialect_.modbusStatements) {
        fail(keyword, name + " is an M350 Modbus statement: the " + std::string(dialect_.name) + " dialect has none");
    }
    switch (keyword.keyword) {
    case Keyword::Popen:
    case Keyword::Pclos:
        block.control = keyword.keyword == Keyword::Popen ? Control::Popen : Control::Pclos;
        while (peek().kind == TokenKind::Comment) {
            next();
        }
        if (peek().kind != TokenKind::End) {
            fail(peek(), "unexpected " + describe(peek()) + " after " + name + " (it stands alone in its block)");
        }
        return;
    case Keyword::Dprnt:
    case Keyword::Bprnt: parsePrintItems(block, keyword); return;
    default: parseModbusArguments(block, keyword); return;
    }
}

// DPRNT[a #b[cd] ...] and BPRNT[a #b[c] ...]: text a, variable b (by number), its digit format.
// FANUC ignores spaces in a block, so they are skipped here too (a space is written `*`).
void BlockParser::parsePrintItems(Block& block, const Token& keyword) {
    const bool binary = keyword.keyword == Keyword::Bprnt;
    const std::string name = binary ? "BPRNT" : "DPRNT";
    const std::string formatHint = binary ? "#100[3] (3 decimals)" : "#100[53] (5 integer digits, 3 decimals)";
    const std::size_t size = line_.size();
    std::size_t i = keyword.offset + keyword.length;
    auto failAt = [&](std::size_t offset, const std::string& message) { fail(columnAt(offset), message); };
    auto skipBlanks = [&] {
        while (i < size && isBlank(line_[i])) {
            ++i;
        }
    };
    skipBlanks();
    if (i >= size || line_[i] != '[') {
        failAt(i, name + " must be followed by [...], e.g. " + name + "[X" + formatHint.substr(0, formatHint.find(' ')) + "]");
    }
    const std::size_t open = i++;
    std::vector<StatementItem> items;
    std::string text;
    std::size_t textStart = 0;
    auto flushText = [&] {
        if (!text.empty()) {
            items.push_back({storage_.text.store(text), kNoExpr, 0, 0, columnAt(textStart)});
            text.clear();
        }
    };
    while (true) {
        skipBlanks();
        if (i >= size) {
            failAt(i, "missing ']' to close " + name + "[ at column " + std::to_string(columnAt(open)));
        }
        const char c = line_[i];
        if (c == ']') {
            ++i;
            break;
        }
        if (c == '#') {
            flushText();
            const std::size_t hash = i++;
            skipBlanks();
            int number = 0;
            std::size_t digits = 0;
            while (i < size && (isDigit(line_[i]) || (digits > 0 && isBlank(line_[i])))) {
                if (isDigit(line_[i])) {
                    number = number * 10 + (line_[i] - '0');
                    if (++digits > 5) {
                        failAt(hash, name + ": variable numbers have at most 5 digits");
                    }
                }
                ++i;
            }
            if (digits == 0) {
                failAt(i, name + " prints a variable by its number: '#' must be followed by digits, e.g. " + formatHint);
            }
            if (i >= size || line_[i] != '[') {
                failAt(i, "#" + std::to_string(number) + " needs its digit format in brackets: " + formatHint);
            }
            const std::size_t formatOpen = i++;
            int format[2] = {0, 0};
            const int wanted = binary ? 1 : 2;
            for (int k = 0; k < wanted; ++k) {
                skipBlanks();
                if (i >= size || !isDigit(line_[i])) {
                    failAt(i, "the digit format of #" + std::to_string(number) + " is " +
                                  (binary ? "one digit, [c]: c decimals" : "two digits, [cd]: c integer digits, d decimals"));
                }
                format[k] = line_[i++] - '0';
            }
            skipBlanks();
            if (i >= size || line_[i] != ']') {
                failAt(i, "missing ']' to close the digit format of #" + std::to_string(number) + " at column " +
                              std::to_string(columnAt(formatOpen)));
            }
            ++i;
            const int integerDigits = binary ? 0 : format[0];
            const int fractionDigits = binary ? format[0] : format[1];
            if (integerDigits + fractionDigits > kMaxPrintDigits || (!binary && integerDigits + fractionDigits == 0)) {
                failAt(formatOpen, "#" + std::to_string(number) + "[" + std::to_string(format[0]) +
                                       (binary ? "" : std::to_string(format[1])) + "]: " +
                                       (binary ? "at most 8 decimals" : "c + d must be 1 to 8 digits"));
            }
            ExprNode variable;
            variable.kind = ExprKind::Variable;
            variable.number = number;
            variable.column = columnAt(hash);
            items.push_back({{}, pool_.add(variable), static_cast<std::uint8_t>(integerDigits),
                             static_cast<std::uint8_t>(fractionDigits), columnAt(hash)});
            continue;
        }
        if (!isPrintText(c)) {
            std::size_t end = i + 1;
            while (end < size && (static_cast<unsigned char>(line_[end]) & 0xC0) == 0x80) {
                ++end;
            }
            failAt(i, name + " text may hold capital letters, digits, * (a space) and + - / . , : = ? ! $ & @ < > ' \"; found '" +
                          std::string(line_.substr(i, end - i)) + "'");
        }
        if (text.empty()) {
            textStart = i;
        }
        text += c == '*' ? ' ' : c;
        ++i;
    }
    flushText();
    skipBlanks();
    if (i < size && line_[i] == '(') {
        const std::size_t close = line_.find(')', i);
        if (close == std::string_view::npos) {
            failAt(i, "comment '(' is not closed with ')'");
        }
        if (block.comment.empty()) {
            block.comment = storage_.text.store(line_.substr(i + 1, close - i - 1));
        }
        i = close + 1;
        skipBlanks();
    }
    if (i < size && line_[i] != ';') {
        failAt(i, "unexpected '" + std::string(1, line_[i]) + "' after " + name + "[...] (it stands alone in its block)");
    }
    block.control = binary ? Control::Bprnt : Control::Dprnt;
    block.statement = storeStatement(items);
}

// The firmware's MSETDATA[X1, X2, X3, X4, X5, X6] and MGETDATA[...] (ModbusStatement.h): six
// arguments, those written as numbers checked here, the others when the line runs. MBYTE2DATA and
// MDATA2BYTE parse, but no public document gives what their arguments mean: `check` flags them and
// a run alarms when it reaches one, instead of guessing.
void BlockParser::parseModbusArguments(Block& block, const Token& keyword) {
    const std::string name = keywordSpelling(keyword.keyword);
    const bool transfer = keyword.keyword == Keyword::MSetData || keyword.keyword == Keyword::MGetData;
    const bool write = keyword.keyword == Keyword::MSetData;
    const std::string usage = transfer ? ModbusStatement::usage(write) : std::string();
    if (peek().kind != TokenKind::LBracket) {
        fail(peek(), name + " must be followed by [...]" + (transfer ? ": " + usage : std::string()) + ", found " +
                         describe(peek()));
    }
    const Token& open = next();
    std::vector<StatementItem> arguments;
    while (true) {
        StatementItem argument;
        argument.column = peek().column;
        argument.value = parseExpression();
        arguments.push_back(argument);
        if (peek().kind != TokenKind::Comma) {
            break;
        }
        next();
    }
    if (peek().kind != TokenKind::RBracket) {
        fail(peek(), "missing ']' to close " + name + "[ at column " + std::to_string(open.column) + ", found " +
                         describe(peek()));
    }
    next();
    while (peek().kind == TokenKind::Comment) {
        next();
    }
    if (peek().kind != TokenKind::End) {
        fail(peek(), "unexpected " + describe(peek()) + " after " + name + "[...]");
    }
    if (transfer) {
        checkModbusTransfer(keyword, write, arguments);
        block.control = write ? Control::MSetData : Control::MGetData;
    } else {
        block.control = Control::ModbusConversion;
        lint(keyword.column, name + " is not simulated: no public document gives the meaning of its arguments, so "
                                    "a run alarms when it reaches this line");
    }
    block.statement = storeStatement(arguments);
}

// The six arguments of MSETDATA or MGETDATA: their count, and the values written as numbers.
void BlockParser::checkModbusTransfer(const Token& keyword, bool write, const std::vector<StatementItem>& arguments) {
    const std::string name = ModbusStatement::name(write);
    const std::string example = write ? "MSETDATA[200,1,0,4,16,300] writes #200-#203 into registers 0-1 of slave 1"
                                      : "MGETDATA[200,1,10,4,3,300] reads registers 10-11 of slave 1 into #200-#203";
    if (arguments.size() == 3) {
        fail(keyword, name + "[slave, register, " + (write ? "value" : "#variable") +
                          "] was this simulator's own form, not the firmware's: the M350 takes six arguments, " +
                          ModbusStatement::usage(write) + ", e.g. " + example);
    }
    if (arguments.size() != ModbusStatement::kCount) {
        fail(keyword, name + " takes 6 arguments, not " + std::to_string(arguments.size()) + ": " +
                          ModbusStatement::usage(write) + ", e.g. " + example);
    }
    // A number as written (-5 included); nothing for an expression, checked when the line runs.
    auto literal = [&](const StatementItem& item) -> std::optional<double> {
        const ExprNode& node = pool_[item.value];
        if (node.kind == ExprKind::Number) {
            return node.number;
        }
        if (node.kind == ExprKind::Unary && pool_[node.lhs].kind == ExprKind::Number) {
            const double v = pool_[node.lhs].number;
            return static_cast<UnaryOp>(node.op) == UnaryOp::Negate ? -v : v;
        }
        return std::nullopt;
    };
    for (int k = 0; k < ModbusStatement::kCount; ++k) {
        const StatementItem& item = arguments[static_cast<std::size_t>(k)];
        if (auto v = literal(item)) {
            if (auto problem = ModbusStatement::argumentProblem(write, k, *v)) {
                fail(item.column, name + ": " + *problem);
            }
        }
    }
    const auto first = literal(arguments[ModbusStatement::FirstVariable]);
    const auto bytes = literal(arguments[ModbusStatement::Bytes]);
    if (first && bytes) {
        if (auto problem = ModbusStatement::spanProblem(static_cast<int>(*first), static_cast<int>(*bytes))) {
            fail(arguments[ModbusStatement::Bytes].column, name + ": " + *problem);
        }
    }
    for (int k : {ModbusStatement::FirstVariable, ModbusStatement::ExceptionVariable}) {
        const StatementItem& item = arguments[static_cast<std::size_t>(k)];
        const ExprNode& node = pool_[item.value];
        if (node.kind == ExprKind::Variable && node.lhs == kNoExpr) {
            const std::string n = std::to_string(static_cast<long long>(node.number));
            note(item.column, name + ": X" + std::to_string(k + 1) + " is a variable's number: #" + n +
                                  " stands for the number #" + n + " holds; write " + n + " to mean #" + n);
        }
    }
}

} // namespace m350::gcode
