#include "core/gcode/StrayBracket.h"

#include "core/common/Message.h"

#include <string_view>
#include <utility>

namespace m350::gcode {

namespace {

// Where a stray ']' stands, in both languages (failStrayBracket's context).
std::string bracketContext(std::string_view context) {
    static const std::pair<std::string_view, std::string_view> words[] = {
        {"IF condition", "IF条件"},        {"WHILE condition", "WHILE条件"}, {"this block", "本程序段"},
        {"this assignment", "本赋值语句"}, {"this expression", "本表达式"},
    };
    for (const auto& [english, chinese] : words) {
        if (english == context) {
            return bilingual(english, chinese);
        }
    }
    return std::string(context);
}

} // namespace

void failStrayBracket(const LineTokens& tokens, LineFindings& findings, const Token& at, const char* context) {
    std::size_t stray = tokens.position();
    std::size_t open = 0;
    for (std::size_t i = 0; i + 1 < stray; ++i) {
        if (tokens[i].kind == TokenKind::LBracket && tokens[i + 1].kind == TokenKind::Hash) {
            open = i + 1;
            break;
        }
        if (tokens[i].kind == TokenKind::Hash && tokens[i + 1].kind == TokenKind::Number) {
            open = i;
            break;
        }
    }
    std::string hint = hashBracketHint(tokens, open, stray);
    const std::string where = bracketContext(context);
    findings.fail(at, hint.empty() ? message("parse_bracket", {where}) : message("parse_bracket_hint", {where, hint}));
}

// For `#1552+#20-1]` or `[#1520+#13-1] NE 0]`: the indirect reference the author most likely meant,
// `#[1552+#20-1]`, built from the text between the '#' and the first ']' after it.
std::string hashBracketHint(const LineTokens& tokens, std::size_t hashToken, std::size_t strayToken) {
    if (hashToken + 1 >= tokens.size() || tokens[hashToken].kind != TokenKind::Hash ||
        tokens[hashToken + 1].kind == TokenKind::LBracket) {
        return {}; // no hint when the reference is already written #[...]
    }
    std::size_t close = hashToken;
    while (close < strayToken && tokens[close].kind != TokenKind::RBracket) {
        ++close;
    }
    std::uint32_t from = tokens[hashToken].offset + 1;
    std::uint32_t to = tokens[close].offset;
    if (to <= from) {
        return {};
    }
    return "#[" + std::string(tokens.line().substr(from, to - from)) + "]";
}

} // namespace m350::gcode
