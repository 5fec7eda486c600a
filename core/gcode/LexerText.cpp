#include "core/gcode/LexerText.h"

#include <optional>
#include <utility>

namespace m350::gcode {

namespace {

std::optional<Keyword> keywordFor(std::string_view upperWord) {
    for (int k = 0; k <= static_cast<int>(Keyword::Bcd); ++k) {
        if (upperWord == keywordSpelling(static_cast<Keyword>(k))) {
            return static_cast<Keyword>(k);
        }
    }
    return std::nullopt;
}

constexpr std::size_t kLongestKeyword = 10; // MBYTE2DATA

bool split(std::string_view rest, KeywordSplit& out) {
    if (rest.empty()) {
        return true;
    }
    if (out.count == KeywordSplit::kMaxParts) {
        return false;
    }
    for (std::size_t length = std::min(kLongestKeyword, rest.size()); length >= 2; --length) {
        if (auto keyword = keywordFor(rest.substr(0, length))) {
            out.keyword[out.count] = *keyword;
            out.length[out.count] = static_cast<std::uint8_t>(length);
            ++out.count;
            if (split(rest.substr(length), out)) {
                return true;
            }
            --out.count;
        }
    }
    return false;
}

} // namespace

KeywordSplit splitKeywords(std::string_view upperWord) {
    KeywordSplit out;
    if (!split(upperWord, out)) {
        out.count = 0;
    }
    return out;
}

const char* fullWidthAscii(std::string_view character) {
    static constexpr std::pair<std::string_view, const char*> table[] = {
        {"（", "("}, {"）", ")"}, {"［", "["}, {"］", "]"}, {"＃", "#"}, {"，", ","}, {"＝", "="},
        {"＋", "+"}, {"－", "-"}, {"＊", "*"}, {"／", "/"}, {"；", ";"}, {"　", " "}, {"＜", "<"}, {"＞", ">"}};
    for (auto [wide, ascii] : table) {
        if (character == wide) {
            return ascii;
        }
    }
    return nullptr;
}

} // namespace m350::gcode
