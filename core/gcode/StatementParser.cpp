#include "core/gcode/StatementParser.h"

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

std::uint32_t StatementParser::storeStatement(const std::vector<StatementItem>& items) {
    storage_.statements.push_back(storage_.statementItems.copy(items));
    return static_cast<std::uint32_t>(storage_.statements.size() - 1);
}

void StatementParser::parse(Block& block, const Token& keyword) {
    const std::string name = keywordSpelling(keyword.keyword);
    const bool output = keyword.keyword >= Keyword::Popen && keyword.keyword <= Keyword::Bprnt;
    if (output && !dialect_.externalOutput) {
        findings_.fail(keyword, message("parse_no_external_output", {name, std::string(dialect_.name)}));
    }
    if (!output && !dialect_.modbusStatements) {
        findings_.fail(keyword, message("parse_no_modbus", {name, std::string(dialect_.name)}));
    }
    switch (keyword.keyword) {
    case Keyword::Popen:
    case Keyword::Pclos:
        block.control = keyword.keyword == Keyword::Popen ? Control::Popen : Control::Pclos;
        while (tokens_.peek().kind == TokenKind::Comment) {
            tokens_.next();
        }
        if (tokens_.peek().kind != TokenKind::End) {
            findings_.fail(tokens_.peek(), message("parse_after_alone", {tokens_.describeWords(tokens_.peek()), name}));
        }
        return;
    case Keyword::Dprnt:
    case Keyword::Bprnt: parsePrintItems(block, keyword); return;
    default: parseModbusArguments(block, keyword); return;
    }
}

// DPRNT[a #b[cd] ...] and BPRNT[a #b[c] ...]: text a, variable b (by number), its digit format.
// FANUC ignores spaces in a block, so they are skipped here too (a space is written `*`).
void StatementParser::parsePrintItems(Block& block, const Token& keyword) {
    const bool binary = keyword.keyword == Keyword::Bprnt;
    const std::string name = binary ? "BPRNT" : "DPRNT";
    const std::string formatHint = binary ? bilingual("#100[3] (3 decimals)", "#100[3]（3位小数）")
                                          : bilingual("#100[53] (5 integer digits, 3 decimals)", "#100[53]（5位整数，3位小数）");
    const std::size_t size = tokens_.line().size();
    std::size_t i = keyword.offset + keyword.length;
    auto failAt = [&](std::size_t offset, const Message& words) { findings_.fail(tokens_.columnAt(offset), words); };
    auto skipBlanks = [&] {
        while (i < size && isBlank(tokens_.line()[i])) {
            ++i;
        }
    };
    skipBlanks();
    if (i >= size || tokens_.line()[i] != '[') {
        failAt(i, message("print_needs_brackets", {name, binary ? "#100[3]" : "#100[53]"}));
    }
    const std::size_t open = i++;
    std::vector<StatementItem> items;
    std::string text;
    std::size_t textStart = 0;
    auto flushText = [&] {
        if (!text.empty()) {
            items.push_back({storage_.text.store(text), kNoExpr, 0, 0, tokens_.columnAt(textStart)});
            text.clear();
        }
    };
    while (true) {
        skipBlanks();
        if (i >= size) {
            failAt(i, message("print_missing_bracket", {name, std::to_string(tokens_.columnAt(open))}));
        }
        const char c = tokens_.line()[i];
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
            while (i < size && (isDigit(tokens_.line()[i]) || (digits > 0 && isBlank(tokens_.line()[i])))) {
                if (isDigit(tokens_.line()[i])) {
                    number = number * 10 + (tokens_.line()[i] - '0');
                    if (++digits > 5) {
                        failAt(hash, message("print_variable_digits", {name}));
                    }
                }
                ++i;
            }
            if (digits == 0) {
                failAt(i, message("print_hash_digits", {name, formatHint}));
            }
            if (i >= size || tokens_.line()[i] != '[') {
                failAt(i, message("print_format_brackets", {std::to_string(number), formatHint}));
            }
            const std::size_t formatOpen = i++;
            int format[2] = {0, 0};
            const int wanted = binary ? 1 : 2;
            for (int k = 0; k < wanted; ++k) {
                skipBlanks();
                if (i >= size || !isDigit(tokens_.line()[i])) {
                    failAt(i, message(binary ? "print_format_bprnt" : "print_format_dprnt", {std::to_string(number)}));
                }
                format[k] = tokens_.line()[i++] - '0';
            }
            skipBlanks();
            if (i >= size || tokens_.line()[i] != ']') {
                failAt(i, message("print_format_missing_bracket", {std::to_string(number), std::to_string(tokens_.columnAt(formatOpen))}));
            }
            ++i;
            const int integerDigits = binary ? 0 : format[0];
            const int fractionDigits = binary ? format[0] : format[1];
            if (integerDigits + fractionDigits > kMaxPrintDigits || (!binary && integerDigits + fractionDigits == 0)) {
                failAt(formatOpen, message(binary ? "print_digits_bprnt" : "print_digits_dprnt",
                                           {std::to_string(number),
                                            std::to_string(format[0]) + (binary ? "" : std::to_string(format[1]))}));
            }
            ExprNode variable;
            variable.kind = ExprKind::Variable;
            variable.number = number;
            variable.column = tokens_.columnAt(hash);
            items.push_back({{}, pool_.add(variable), static_cast<std::uint8_t>(integerDigits),
                             static_cast<std::uint8_t>(fractionDigits), tokens_.columnAt(hash)});
            continue;
        }
        if (!isPrintText(c)) {
            std::size_t end = i + 1;
            while (end < size && (static_cast<unsigned char>(tokens_.line()[end]) & 0xC0) == 0x80) {
                ++end;
            }
            failAt(i, message("print_text_character", {name, std::string(tokens_.line().substr(i, end - i))}));
        }
        if (text.empty()) {
            textStart = i;
        }
        text += c == '*' ? ' ' : c;
        ++i;
    }
    flushText();
    skipBlanks();
    if (i < size && tokens_.line()[i] == '(') {
        const std::size_t close = tokens_.line().find(')', i);
        if (close == std::string_view::npos) {
            failAt(i, message("lex_unclosed_comment"));
        }
        if (block.comment.empty()) {
            block.comment = storage_.text.store(tokens_.line().substr(i + 1, close - i - 1));
        }
        i = close + 1;
        skipBlanks();
    }
    if (i < size && tokens_.line()[i] != ';') {
        failAt(i, message("print_after", {std::string(1, tokens_.line()[i]), name}));
    }
    block.control = binary ? Control::Bprnt : Control::Dprnt;
    block.statement = storeStatement(items);
}

// The firmware's MSETDATA[X1, X2, X3, X4, X5, X6] and MGETDATA[...] (ModbusStatement.h): six
// arguments, those written as numbers checked here, the others when the line runs. MBYTE2DATA and
// MDATA2BYTE parse, but no public document gives what their arguments mean: `check` flags them and
// a run alarms when it reaches one, instead of guessing.
void StatementParser::parseModbusArguments(Block& block, const Token& keyword) {
    const std::string name = keywordSpelling(keyword.keyword);
    const bool transfer = keyword.keyword == Keyword::MSetData || keyword.keyword == Keyword::MGetData;
    const bool write = keyword.keyword == Keyword::MSetData;
    if (tokens_.peek().kind != TokenKind::LBracket) {
        findings_.fail(tokens_.peek(), !transfer ? message("modbus_needs_brackets", {name, tokens_.describeWords(tokens_.peek())})
                     : message(write ? "msetdata_needs_brackets" : "mgetdata_needs_brackets", {tokens_.describeWords(tokens_.peek())}));
    }
    const Token& open = tokens_.next();
    std::vector<StatementItem> arguments;
    while (true) {
        StatementItem argument;
        argument.column = tokens_.peek().column;
        argument.value = expressions_.parseExpression();
        arguments.push_back(argument);
        if (tokens_.peek().kind != TokenKind::Comma) {
            break;
        }
        tokens_.next();
    }
    if (tokens_.peek().kind != TokenKind::RBracket) {
        findings_.fail(tokens_.peek(), message("parse_missing_bracket_of", {name, std::to_string(open.column), tokens_.describeWords(tokens_.peek())}));
    }
    tokens_.next();
    while (tokens_.peek().kind == TokenKind::Comment) {
        tokens_.next();
    }
    if (tokens_.peek().kind != TokenKind::End) {
        findings_.fail(tokens_.peek(), message("parse_after_statement", {tokens_.describeWords(tokens_.peek()), name}));
    }
    if (transfer) {
        checkModbusTransfer(keyword, write, arguments);
        block.control = write ? Control::MSetData : Control::MGetData;
    } else {
        block.control = Control::ModbusConversion;
        findings_.lint(keyword.column, message("lint_modbus_conversion", {name}));
    }
    block.statement = storeStatement(arguments);
}

// The six arguments of MSETDATA or MGETDATA: their count, and the values written as numbers.
void StatementParser::checkModbusTransfer(const Token& keyword, bool write, const std::vector<StatementItem>& arguments) {
    const std::string name = ModbusStatement::name(write);
    if (arguments.size() == 3) {
        findings_.fail(keyword, message(write ? "msetdata_old_form" : "mgetdata_old_form"));
    }
    if (arguments.size() != ModbusStatement::kCount) {
        findings_.fail(keyword, message(write ? "msetdata_argument_count" : "mgetdata_argument_count",
                              {std::to_string(arguments.size())}));
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
                findings_.fail(item.column, *problem);
            }
        }
    }
    const auto first = literal(arguments[ModbusStatement::FirstVariable]);
    const auto bytes = literal(arguments[ModbusStatement::Bytes]);
    if (first && bytes) {
        if (auto problem = ModbusStatement::spanProblem(write, static_cast<int>(*first), static_cast<int>(*bytes))) {
            findings_.fail(arguments[ModbusStatement::Bytes].column, *problem);
        }
    }
    for (int k : {ModbusStatement::FirstVariable, ModbusStatement::ExceptionVariable}) {
        const StatementItem& item = arguments[static_cast<std::size_t>(k)];
        const ExprNode& node = pool_[item.value];
        if (node.kind == ExprKind::Variable && node.lhs == kNoExpr) {
            const std::string n = std::to_string(static_cast<long long>(node.number));
            findings_.note(item.column, message("note_modbus_variable_number", {name, std::to_string(k + 1), n}));
        }
    }
}

} // namespace m350::gcode
