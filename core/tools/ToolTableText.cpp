#include "core/tools/ToolTableText.h"

#include "core/params/ParamsFileWriter.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace m350::tools {

namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }
bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::string typeKeys() {
    std::string keys;
    for (std::size_t i = 0; i < kToolTypeCount; ++i) {
        keys += (i ? ", " : "") + std::string(toolTypeKey(static_cast<ToolType>(i)));
    }
    return keys;
}

struct Item {
    std::string_view text;
    int column = 0;
};

// The group's items, or nullopt when the group is no extras group (an item without '=').
std::optional<std::vector<Item>> groupItems(std::string_view inner, int column) {
    std::vector<Item> items;
    std::size_t i = 0;
    while (i < inner.size()) {
        while (i < inner.size() && blank(inner[i])) ++i;
        std::size_t start = i;
        while (i < inner.size() && !blank(inner[i])) ++i;
        if (i > start) {
            std::string_view item = inner.substr(start, i - start);
            if (item.find('=') == std::string_view::npos) {
                return std::nullopt;
            }
            items.push_back({item, column + static_cast<int>(start)});
        }
    }
    if (items.empty()) {
        return std::nullopt;
    }
    return items;
}

std::optional<std::string> readItem(const Item& item, CommentParts& parts) {
    const std::size_t eq = item.text.find('=');
    const std::string_view key = item.text.substr(0, eq);
    const std::string_view value = item.text.substr(eq + 1);
    const std::string shown = "'" + std::string(item.text) + "'";
    if (key == "rpm") {
        if (parts.maxRpm) return shown + ": rpm is given twice";
        std::optional<double> rpm = parseTableNumber(value);
        if (!rpm || *rpm <= 0.0) return shown + ": rpm needs a positive number (the tool's maximum spindle speed)";
        parts.maxRpm = rpm;
    } else if (key == "teeth") {
        if (parts.teeth) return shown + ": teeth is given twice";
        std::optional<int> teeth = parseWholeNumber(value);
        if (!teeth || *teeth < 1) return shown + ": teeth needs a whole number from 1";
        parts.teeth = teeth;
    } else if (key == "type") {
        if (parts.type) return shown + ": type is given twice";
        std::optional<ToolType> type = toolTypeFromKey(value);
        if (!type) return shown + ": the types are " + typeKeys();
        parts.type = type;
    } else if (key == "hwear" || key == "dwear") {
        std::optional<double>& wear = key == "hwear" ? parts.lengthWear : parts.radiusWear;
        if (wear) return shown + ": " + std::string(key) + " is given twice";
        wear = parseTableNumber(value);
        if (!wear) return shown + ": " + std::string(key) + " needs a number (FANUC offset memory C's wear)";
    } else {
        return shown + ": the extras are rpm, teeth, type, hwear and dwear";
    }
    return std::nullopt;
}

} // namespace

std::optional<double> parseTableNumber(std::string_view text) {
    std::size_t i = 0;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    bool digits = false;
    while (i < text.size() && digit(text[i])) { ++i; digits = true; }
    if (i < text.size() && text[i] == '.') {
        ++i;
        while (i < text.size() && digit(text[i])) { ++i; digits = true; }
    }
    if (!digits) {
        return std::nullopt;
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        const std::size_t exponent = i;
        while (i < text.size() && digit(text[i])) ++i;
        if (i == exponent) {
            return std::nullopt;
        }
    }
    if (i != text.size()) {
        return std::nullopt;
    }
    double value = 0.0;
    const char* first = text.data() + (text[0] == '+' ? 1 : 0);
    auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

std::optional<int> parseWholeNumber(std::string_view text) {
    std::optional<double> v = parseTableNumber(text);
    if (!v || *v != std::trunc(*v) || std::abs(*v) > static_cast<double>(std::numeric_limits<int>::max())) {
        return std::nullopt;
    }
    return static_cast<int>(*v);
}

std::string tableNumber(double value) { return params::tomlNumber(value); }

CommentParts splitComment(std::string_view comment, int firstColumn) {
    CommentParts parts;
    const std::string_view body = trimmed(comment);
    parts.text = std::string(body);
    const std::size_t open = body.rfind('{');
    if (body.empty() || body.back() != '}' || open == std::string_view::npos) {
        return parts;
    }
    const int groupColumn = firstColumn + static_cast<int>(body.data() - comment.data() + open) + 1;
    std::optional<std::vector<Item>> items = groupItems(body.substr(open + 1, body.size() - open - 2), groupColumn);
    if (!items) {
        return parts;
    }
    CommentParts read;
    for (const Item& item : *items) {
        if (auto problem = readItem(item, read)) {
            parts.problems.push_back({item.column, *problem});
        }
    }
    if (!parts.problems.empty()) {
        return parts;
    }
    read.text = std::string(trimmed(body.substr(0, open)));
    return read;
}

std::string joinComment(const ToolEntry& entry) {
    if (!entry.hasExtras()) {
        return entry.comment;
    }
    std::string group;
    auto item = [&group](const std::string& text) { group += (group.empty() ? "" : " ") + text; };
    if (entry.maxRpm) item("rpm=" + tableNumber(*entry.maxRpm));
    if (entry.teeth) item("teeth=" + std::to_string(*entry.teeth));
    if (entry.type) item("type=" + std::string(toolTypeKey(*entry.type)));
    if (entry.lengthWear) item("hwear=" + tableNumber(*entry.lengthWear));
    if (entry.radiusWear) item("dwear=" + tableNumber(*entry.radiusWear));
    return entry.comment + (entry.comment.empty() ? "" : " ") + "{" + group + "}";
}

} // namespace m350::tools
