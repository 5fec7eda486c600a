#include "core/params/ParamsFileWriter.h"

#include <charconv>
#include <vector>

namespace m350::params {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && (blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// "[params]" -> "params"; "[[x]]" and other lines -> nullopt. A comment may follow the header.
std::optional<std::string_view> tableHeader(std::string_view line) {
    line = trimmed(line);
    if (line.size() < 2 || line[0] != '[' || line[1] == '[') return std::nullopt;
    auto close = line.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    return trimmed(line.substr(1, close - 1));
}

// Where the value of a `N = value` line lies, and N.
struct Entry {
    int key = 0;
    std::size_t valueBegin = 0, valueEnd = 0;
};

std::optional<Entry> numberEntry(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && blank(line[i])) ++i;
    bool quoted = i < line.size() && line[i] == '"';
    if (quoted) ++i;
    Entry entry;
    auto [end, ec] = std::from_chars(line.data() + i, line.data() + line.size(), entry.key);
    if (ec != std::errc()) return std::nullopt;
    i = static_cast<std::size_t>(end - line.data());
    if (quoted && (i >= line.size() || line[i++] != '"')) return std::nullopt;
    while (i < line.size() && blank(line[i])) ++i;
    if (i >= line.size() || line[i] != '=') return std::nullopt;
    ++i;
    while (i < line.size() && blank(line[i])) ++i;
    entry.valueBegin = i;
    while (i < line.size() && !blank(line[i]) && line[i] != '#' && line[i] != '\r') ++i;
    entry.valueEnd = i;
    return entry;
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        lines.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

} // namespace

std::string tomlNumber(double value) {
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, result.ptr);
    return text == "-0" ? "0" : text;
}

std::string setTomlNumbers(std::string_view text, std::string_view table, const std::map<int, double>& values,
                           bool addMissing) {
    std::vector<std::string> lines = splitLines(text);
    std::map<int, double> missing = values;
    bool inTable = false;
    std::optional<std::size_t> lastEntry, header;
    for (std::size_t n = 0; n < lines.size(); ++n) {
        std::string& line = lines[n];
        if (auto name = tableHeader(line)) {
            inTable = *name == table;
            if (inTable) header = n;
            continue;
        }
        if (!inTable) continue;
        auto entry = numberEntry(line);
        if (!entry) continue;
        lastEntry = n;
        auto value = values.find(entry->key);
        if (value == values.end()) continue;
        line.replace(entry->valueBegin, entry->valueEnd - entry->valueBegin, tomlNumber(value->second));
        missing.erase(entry->key);
    }
    std::vector<std::string> added;
    if (!addMissing) missing.clear();
    for (auto [key, value] : missing) added.push_back(std::to_string(key) + " = " + tomlNumber(value));
    if (!header && !added.empty()) {
        if (!lines.empty() && !trimmed(lines.back()).empty()) lines.emplace_back();
        lines.push_back("[" + std::string(table) + "]");
        header = lines.size() - 1;
    }
    if (!added.empty()) {
        std::size_t at = (lastEntry ? *lastEntry : *header) + 1;
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), added.begin(), added.end());
    }
    std::string out;
    for (const std::string& line : lines) out += line + '\n';
    return out;
}

} // namespace m350::params
