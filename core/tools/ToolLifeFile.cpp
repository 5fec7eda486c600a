#include "core/tools/ToolLifeFile.h"

#include "core/files/MachineFileRead.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace m350::tools {

namespace {

// A bad item of a line: what is wrong and the field it is in (its column).
struct LineError {
    Message words;
    std::string_view at;
};

std::vector<std::string_view> fieldsOf(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    auto blank = [&](std::size_t k) { return line[k] == ' ' || line[k] == '\t' || line[k] == '\r'; };
    while (i < line.size()) {
        while (i < line.size() && blank(i)) {
            ++i;
        }
        std::size_t start = i;
        while (i < line.size() && !blank(i)) {
            ++i;
        }
        if (i > start) {
            fields.push_back(line.substr(start, i - start));
        }
    }
    return fields;
}

int number(std::string_view text, int low, int high, std::string_view what) {
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || value < low || value > high) {
        throw LineError{message("life_file_number", {std::string(what), std::to_string(low), std::to_string(high), std::string(text)}),
                        text};
    }
    return value;
}

LifeKind kindOf(std::string_view text) {
    if (text == "count") {
        return LifeKind::Count;
    }
    if (text == "minutes") {
        return LifeKind::Minutes;
    }
    throw LineError{message("life_file_kind", {std::string(text)}), text};
}

// `key value key value ...` after the item's own number; every key once, all required.
std::vector<int> namedNumbers(const std::vector<std::string_view>& f, std::size_t from,
                              const std::vector<std::pair<std::string_view, int>>& keys) {
    std::vector<int> values(keys.size(), -1);
    for (std::size_t i = from; i < f.size(); i += 2) {
        std::size_t k = 0;
        while (k < keys.size() && keys[k].first != f[i]) {
            ++k;
        }
        if (k == keys.size() || i + 1 >= f.size()) {
            throw LineError{message(k == keys.size() ? "life_file_unknown_word" : "life_file_needs_value", {std::string(f[i])}),
                            f[i]};
        }
        if (values[k] >= 0) {
            throw LineError{message("life_file_word_twice", {std::string(f[i])}), f[i]};
        }
        values[k] = number(f[i + 1], 0, keys[k].second, f[i]);
    }
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (values[k] < 0) {
            throw LineError{message("life_file_missing_word", {std::string(keys[k].first)}), f.back()};
        }
    }
    return values;
}

void parseSetting(const std::vector<std::string_view>& f, LifeData& data) {
    if (data.fromParameters && (f[0] == "gs" || f[0] == "ignore" || f[0] == "ltm")) {
        const std::string where = f[0] == "gs"       ? bilingual("parameter 6800 #0 GS1 / #1 GS2", "参数6800 #0 GS1 / #1 GS2")
                                  : f[0] == "ignore" ? bilingual("parameter 6810", "参数6810")
                                                     : bilingual("parameter 6800 #2 LTM", "参数6800 #2 LTM");
        throw LineError{message("life_file_fanuc_setting", {std::string(f[0]), where}), f[0]};
    }
    if (f[0] == "gs" && f.size() == 2) {
        data.gs = number(f[1], 0, 3, "gs");
    } else if (f[0] == "ignore" && f.size() == 2) {
        data.ignoreNumber = number(f[1], 1, 9999, "ignore");
    } else if (f[0] == "ltm" && f.size() == 2) {
        data.defaultKind = kindOf(f[1]);
    } else {
        throw LineError{message("life_file_expected_line"), f[0]};
    }
}

LifeGroup parseGroup(const std::vector<std::string_view>& f, const LifeData& data) {
    if (f.size() != 5 || f[2] != "life") {
        throw LineError{message("life_file_group_line"), f.size() > 2 ? f[2] : f[0]};
    }
    LifeGroup group;
    group.number = number(f[1], 1, 128, bilingual("the group number", "刀具组号"));
    group.life = number(f[3], 1, 99999, bilingual("the life", "寿命值"));
    group.kind = kindOf(f[4]);
    if (data.group(group.number)) {
        throw LineError{message("life_file_group_twice", {std::to_string(group.number)}), f[1]};
    }
    return group;
}

LifeTool parseTool(const std::vector<std::string_view>& f, const LifeGroup& group) {
    if (f.size() < 2) {
        throw LineError{message("life_file_tool_line"), f[0]};
    }
    LifeTool tool;
    tool.tool = number(f[1], 1, 9999, bilingual("the tool number", "刀号"));
    for (const LifeTool& sister : group.tools) {
        if (sister.tool == tool.tool) {
            throw LineError{message("life_file_tool_twice", {std::to_string(tool.tool), std::to_string(group.number)}), f[1]};
        }
    }
    std::vector<int> v = namedNumbers(f, 2, {{"h", 999}, {"d", 999}, {"used", 9999999}});
    tool.h = v[0];
    tool.d = v[1];
    tool.used = v[2];
    return tool;
}

// Reads the lines one by one, keeping each group's own lines so that a group refused at the end
// (no tools, beyond the capacity) is kept as text with them.
class LifeReader {
public:
    LifeReader(std::string file, const LifeData* settings) : file_(std::move(file)) {
        if (settings) {
            out_.data.gs = settings->gs;
            out_.data.ignoreNumber = settings->ignoreNumber;
            out_.data.defaultKind = settings->defaultKind;
            out_.data.extendedEntry = settings->extendedEntry;
            out_.data.fromParameters = settings->fromParameters;
        }
    }

    void line(std::string_view raw, std::uint32_t number) {
        std::string_view text = raw.substr(0, raw.find_last_not_of("\r") + 1);
        if (text.substr(0, kUnreadPrefix.size()) == kUnreadPrefix) {
            out_.data.unreadLines.emplace_back(text.substr(kUnreadPrefix.size()));
            return;
        }
        std::vector<std::string_view> f = fieldsOf(text.substr(0, text.find(';')));
        if (f.empty()) {
            return;
        }
        try {
            if (f[0] == "tool") {
                LifeGroup* group = out_.data.group(currentGroup_);
                if (!group) {
                    throw LineError{message("life_file_tool_first"), f[0]};
                }
                group->tools.push_back(parseTool(f, *group));
                groupLines_[currentGroup_].emplace_back(text);
            } else if (f[0] == "group") {
                currentGroup_ = 0; // a bad group line takes its tool lines with it
                LifeGroup group = parseGroup(f, out_.data);
                currentGroup_ = group.number;
                groupFirstLine_[group.number] = number;
                groupLines_[group.number] = {std::string(text)};
                out_.data.putGroup(std::move(group));
            } else {
                parseSetting(f, out_.data);
            }
        } catch (const LineError& e) {
            const auto column = static_cast<std::uint32_t>(e.at.data() - text.data()) + 1;
            out_.issues.push_back({file_, number, column, e.words.english(), e.words});
            out_.data.unreadLines.emplace_back(text);
        }
    }

    ParsedToolLife finish() {
        std::vector<int> refused;
        for (const LifeGroup& g : out_.data.groups) {
            std::optional<Message> problem;
            if (g.tools.empty()) {
                problem = message("life_file_group_no_tools", {std::to_string(g.number)});
            } else if (auto capacity = out_.data.capacityProblem(g)) {
                problem = *capacity;
            }
            if (problem) {
                out_.issues.push_back({file_, groupFirstLine_[g.number], 1, problem->english(), *problem});
                refused.push_back(g.number);
            }
        }
        for (int number : refused) {
            out_.data.removeGroup(number);
            for (std::string& text : groupLines_[number]) {
                out_.data.unreadLines.push_back(std::move(text));
            }
        }
        return std::move(out_);
    }

private:
    std::string file_;
    ParsedToolLife out_;
    int currentGroup_ = 0;
    std::map<int, std::uint32_t> groupFirstLine_;
    std::map<int, std::vector<std::string>> groupLines_;
};

} // namespace

std::string LifeFileIssue::text(MessageLanguage language) const {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
           messageText("life_file_line_skipped", {words.id.empty() ? message : bilingual(words)}, language);
}

ParsedToolLife parseToolLife(std::string_view text, const std::string& file, const LifeData* settings) {
    LifeReader reader(file, settings);
    std::uint32_t lineNumber = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        std::string_view line = text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
        at = end == std::string_view::npos ? text.size() : end + 1;
        reader.line(line, ++lineNumber);
    }
    return reader.finish();
}

std::variant<ParsedToolLife, Message> loadToolLife(const std::string& folder, const LifeData* settings) {
    std::filesystem::path path = std::filesystem::path(folder) / kToolLifeFile;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        return parseToolLife("", path.string(), settings);
    }
    std::string text;
    if (auto why = files::readMachineFile(path, text)) {
        return message("life_file_unreadable", {bilingual(*why)});
    }
    return parseToolLife(text, path.string(), settings);
}

std::string formatToolLife(const LifeData& data) {
    std::ostringstream out;
    out << "; tool life management data (FANUC 0i style), kept by the controller\n";
    if (data.fromParameters) {
        out << "; GS1/GS2 and LTM are parameter 6800, EXT 6801 #6, the ignore number 6810 (params.toml)\n";
    } else {
        out << "gs " << data.gs << "          ; GS2*2+GS1: 0 = 16x16, 1 = 64x4 (GS1), 2 = 32x8 (GS2), 3 = 128x2\n"
            << "ignore " << data.ignoreNumber << "    ; T(ignore+n) selects group n\n"
            << "ltm " << (data.defaultKind == LifeKind::Count ? "count" : "minutes") << '\n';
    }
    for (const LifeGroup& g : data.groups) {
        out << "group " << g.number << " life " << g.life << ' '
            << (g.kind == LifeKind::Count ? "count" : "minutes") << '\n';
        for (const LifeTool& t : g.tools) {
            out << "tool " << t.tool << " h " << t.h << " d " << t.d << " used " << t.used << '\n';
        }
    }
    for (const std::string& line : data.unreadLines) {
        out << kUnreadPrefix << line << '\n';
    }
    return out.str();
}

} // namespace m350::tools
