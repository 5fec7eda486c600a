#include "core/tools/ToolLifeFile.h"

#include "core/config/AtomicFile.h"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace m350::tools {

namespace {

struct LineError {
    std::string message;
};

std::vector<std::string_view> fieldsOf(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) {
            ++i;
        }
        std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
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
        throw LineError{std::string(what) + " must be a whole number from " + std::to_string(low) + " to " +
                        std::to_string(high) + ", not '" + std::string(text) + "'"};
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
    throw LineError{"the life is counted in 'count' or 'minutes', not '" + std::string(text) + "'"};
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
            throw LineError{k == keys.size() ? "unknown word '" + std::string(f[i]) + "'"
                                             : "'" + std::string(f[i]) + "' needs a value"};
        }
        values[k] = number(f[i + 1], 0, keys[k].second, f[i]);
    }
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (values[k] < 0) {
            throw LineError{"missing '" + std::string(keys[k].first) + "'"};
        }
    }
    return values;
}

void parseSetting(const std::vector<std::string_view>& f, LifeData& data) {
    if (f[0] == "gs" && f.size() == 2) {
        data.gs = number(f[1], 0, 3, "gs");
    } else if (f[0] == "ignore" && f.size() == 2) {
        data.ignoreNumber = number(f[1], 1, 9999, "ignore");
    } else if (f[0] == "ltm" && f.size() == 2) {
        data.defaultKind = kindOf(f[1]);
    } else {
        throw LineError{"expected 'gs N', 'ignore N', 'ltm count|minutes', 'group N life L count|minutes' or "
                        "'tool T h H d D used U'"};
    }
}

LifeGroup parseGroup(const std::vector<std::string_view>& f, const LifeData& data) {
    if (f.size() != 5 || f[2] != "life") {
        throw LineError{"a group line is 'group N life L count|minutes'"};
    }
    LifeGroup group;
    group.number = number(f[1], 1, 128, "the group number");
    group.life = number(f[3], 1, 99999, "the life");
    group.kind = kindOf(f[4]);
    if (data.group(group.number)) {
        throw LineError{"group " + std::to_string(group.number) + " is given twice"};
    }
    return group;
}

LifeTool parseTool(const std::vector<std::string_view>& f) {
    LifeTool tool;
    tool.tool = number(f.size() > 1 ? f[1] : std::string_view(), 1, 9999, "the tool number");
    std::vector<int> v = namedNumbers(f, 2, {{"h", 999}, {"d", 999}, {"used", 9999999}});
    tool.h = v[0];
    tool.d = v[1];
    tool.used = v[2];
    return tool;
}

} // namespace

std::variant<LifeData, LifeFileError> parseToolLife(std::string_view text, const std::string& file) {
    LifeData data;
    int currentGroup = 0;
    std::map<int, std::uint32_t> groupLines;
    std::uint32_t lineNumber = 0;
    std::size_t at = 0;
    while (at <= text.size()) {
        std::size_t end = text.find('\n', at);
        std::string_view line = text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
        at = end == std::string_view::npos ? text.size() + 1 : end + 1;
        ++lineNumber;
        line = line.substr(0, line.find(';'));
        std::vector<std::string_view> f = fieldsOf(line);
        if (f.empty()) {
            continue;
        }
        try {
            if (f[0] == "tool") {
                LifeGroup* group = data.group(currentGroup);
                if (!group) {
                    throw LineError{"a tool line must follow its 'group' line"};
                }
                group->tools.push_back(parseTool(f));
            } else if (f[0] == "group") {
                LifeGroup group = parseGroup(f, data);
                currentGroup = group.number;
                groupLines[group.number] = lineNumber;
                data.putGroup(std::move(group));
            } else {
                parseSetting(f, data);
            }
        } catch (const LineError& e) {
            return LifeFileError{file, lineNumber, e.message};
        }
    }
    for (const LifeGroup& g : data.groups) {
        if (g.tools.empty()) {
            return LifeFileError{file, groupLines[g.number], "group " + std::to_string(g.number) + " has no tools"};
        }
        if (auto problem = data.capacityProblem(g)) {
            return LifeFileError{file, groupLines[g.number], *problem};
        }
    }
    return data;
}

std::variant<LifeData, LifeFileError> loadToolLife(const std::string& folder) {
    std::filesystem::path path = std::filesystem::path(folder) / kToolLifeFile;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        return LifeData{};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return LifeFileError{path.string(), 0, "cannot read the file"};
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseToolLife(text.str(), path.string());
}

std::string formatToolLife(const LifeData& data) {
    std::ostringstream out;
    out << "; tool life management data (FANUC 0i style), kept by the controller\n"
        << "gs " << data.gs << "          ; GS2*2+GS1: 0 = 16x16, 1 = 32x8, 2 = 64x4, 3 = 128x2\n"
        << "ignore " << data.ignoreNumber << "    ; T(ignore+n) selects group n\n"
        << "ltm " << (data.defaultKind == LifeKind::Count ? "count" : "minutes") << '\n';
    for (const LifeGroup& g : data.groups) {
        out << "group " << g.number << " life " << g.life << ' '
            << (g.kind == LifeKind::Count ? "count" : "minutes") << '\n';
        for (const LifeTool& t : g.tools) {
            out << "tool " << t.tool << " h " << t.h << " d " << t.d << " used " << t.used << '\n';
        }
    }
    return out.str();
}

std::optional<std::string> saveToolLife(const std::string& folder, const LifeData& data) {
    return config::writeFileAtomically(std::filesystem::path(folder) / kToolLifeFile, formatToolLife(data));
}

} // namespace m350::tools
