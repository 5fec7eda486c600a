#include "core/params/ParameterCatalogue.h"
#include "core/common/ResourceDirectory.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>
#include <system_error>

namespace m350::params {

namespace {

constexpr std::string_view kHeader =
    "number\tgroup\tgroup_zh\tgroup_en\tname_zh\tname_en\tunit\ttype\tmin\tmax\toptions\tdefault\thidden";
constexpr std::size_t kColumns = 13;

struct LineError {
    std::string message;
};

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}

double parseNumber(std::string_view text, std::string_view what) {
    double value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw LineError{std::string(what) + " '" + std::string(text) + "' is not a number"};
    return value == 0 ? 0.0 : value; // the source writes "-0" for one minimum; show it as 0
}

int parseInt(std::string_view text, std::string_view what) {
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        throw LineError{std::string(what) + " '" + std::string(text) + "' is not a whole number"};
    return value;
}

// Why a name is not text a panel can show, or nothing: the catalogue is UTF-8, and its names are
// Chinese, English or Russian. Bytes that are not UTF-8 (GBK written as is) and GBK that was once
// read as Latin-1 (×Ô¶¨ÒåG´úÂëºÅ for 自定义G代码号: every GBK byte of a Chinese character
// becomes a code point U+0080-U+00FF, so they come in runs) are refused.
std::optional<std::string> notText(std::string_view text) {
    bool previousLatin1 = false;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3
                                                   : (lead >> 3) == 0x1E ? 4 : 0;
        bool valid = length != 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k) {
            valid = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
        }
        if (!valid) {
            return "is not UTF-8 at its byte " + std::to_string(i + 1) + " (GBK? the catalogue is UTF-8)";
        }
        // U+0080-U+00FF is 0xC2 or 0xC3 and one continuation byte
        const bool latin1 = length == 2 && (lead == 0xC2 || lead == 0xC3);
        if (latin1 && previousLatin1) {
            return "looks like GBK text read as Latin-1: write the text it stands for "
                   "(scripts/gen-parameter-catalogue.py decodes it)";
        }
        previousLatin1 = latin1;
        i += length;
    }
    return std::nullopt;
}

std::string checkedName(std::string_view text, std::string_view field) {
    if (auto why = notText(text)) {
        const bool printable = why->rfind("is not UTF-8", 0) != 0; // a message stays UTF-8 itself
        throw LineError{std::string(field) + (printable ? " '" + std::string(text) + "' " : " ") + *why};
    }
    return std::string(text);
}

// "zh/en" splits at the first '/' after which no CJK follows, since Chinese option names may hold
// a '/' themselves ("脉冲/度/pulse/deg"). UTF-8 lead bytes 0xE3 and up start code points from U+3000
// (CJK punctuation, ideographs, full-width forms).
ParameterOption parseOption(std::string_view text) {
    auto equals = text.find('=');
    if (equals == std::string_view::npos) throw LineError{"option '" + std::string(text) + "' lacks '='"};
    ParameterOption option;
    option.value = parseNumber(trim(text.substr(0, equals)), "option value");
    std::string_view names = trim(text.substr(equals + 1));
    auto lastCjk = std::find_if(names.rbegin(), names.rend(),
                                [](char c) { return static_cast<unsigned char>(c) >= 0xE3; });
    auto slash = names.find('/', static_cast<std::size_t>(names.rend() - lastCjk));
    if (slash == std::string_view::npos)
        throw LineError{"option '" + std::string(text) + "' is not value=zh/en"};
    option.zh = checkedName(names.substr(0, slash), "option name");
    option.en = checkedName(names.substr(slash + 1), "option name");
    return option;
}

// The fields of a row, without a vector per row (m350-sim reads the whole catalogue at start-up).
std::array<std::string_view, kColumns> columns(std::string_view line) {
    std::array<std::string_view, kColumns> fields;
    std::size_t count = 0;
    for (std::size_t start = 0;; ++count) {
        const std::size_t end = line.find('\t', start);
        if (count < kColumns) {
            fields[count] = line.substr(start, end == std::string_view::npos ? end : end - start);
        }
        if (end == std::string_view::npos) {
            break;
        }
        start = end + 1;
    }
    if (count + 1 != kColumns)
        throw LineError{"expected " + std::to_string(kColumns) + " tab-separated fields, found " +
                        std::to_string(count + 1)};
    return fields;
}

ParameterInfo parseRow(std::string_view line) {
    const auto f = columns(line);
    ParameterInfo p;
    p.number = parseInt(f[0], "number");
    p.group = parseInt(f[1], "group");
    p.groupZh = checkedName(f[2], "group_zh");
    p.groupEn = checkedName(f[3], "group_en");
    p.nameZh = checkedName(f[4], "name_zh");
    p.nameEn = checkedName(f[5], "name_en");
    p.unit = f[6];
    if (f[7] == "int") p.type = ParameterInfo::Type::Int;
    else if (f[7] == "real") p.type = ParameterInfo::Type::Real;
    else if (f[7] == "select") p.type = ParameterInfo::Type::Select;
    else throw LineError{"type '" + std::string(f[7]) + "' is not int, real or select"};
    p.min = parseNumber(f[8], "min");
    p.max = parseNumber(f[9], "max");
    if (p.min > p.max) throw LineError{"min is above max"};
    if (!f[10].empty())
        for (std::string_view option : split(f[10], ';')) p.options.push_back(parseOption(trim(option)));
    if (p.type == ParameterInfo::Type::Select && p.options.empty())
        throw LineError{"select parameter without options"};
    // The CAM-teach rows have no factory default; 0 (kept within range) is what a blank form shows.
    p.defaultValue = f[11].empty() ? std::clamp(0.0, p.min, p.max) : parseNumber(f[11], "default");
    if (f[12] != "0" && f[12] != "1") throw LineError{"hidden must be 0 or 1"};
    p.hidden = f[12] == "1";
    return p;
}

std::string formatNumber(double value) {
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

} // namespace

std::variant<ParameterCatalogue, std::string> ParameterCatalogue::load(const std::string& tsvPath) {
    std::ifstream in(tsvPath, std::ios::binary);
    if (!in) return "cannot open parameter catalogue " + tsvPath;
    ParameterCatalogue catalogue;
    catalogue.params_.reserve(640); // the bundled catalogue's 584 rows, without regrowing
    std::string line;
    int lineNumber = 0;
    try {
        while (std::getline(in, line)) {
            ++lineNumber;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (lineNumber == 1) {
                if (line != kHeader) throw LineError{"header is not the parameter catalogue's"};
                continue;
            }
            if (line.empty()) continue;
            ParameterInfo p = parseRow(line);
            if (!catalogue.index_.emplace(p.number, catalogue.params_.size()).second)
                throw LineError{"parameter " + std::to_string(p.number) + " appears twice"};
            catalogue.params_.push_back(std::move(p));
        }
    } catch (const LineError& e) {
        return tsvPath + ":" + std::to_string(lineNumber) + ": " + e.message;
    }
    if (lineNumber == 0) return tsvPath + ":1: file is empty";
    return catalogue;
}

std::string ParameterCatalogue::bundledPath() {
    return resourceDirectory() + "/parameters/m350-parameters.tsv";
}

const std::variant<ParameterCatalogue, std::string>& ParameterCatalogue::bundled() {
    static const std::variant<ParameterCatalogue, std::string> catalogue = load(bundledPath());
    return catalogue;
}

const ParameterInfo* ParameterCatalogue::find(int number) const {
    auto it = index_.find(number);
    return it == index_.end() ? nullptr : &params_[it->second];
}

std::optional<Message> ParameterCatalogue::validate(int number, double value) const {
    const ParameterInfo* p = find(number);
    if (p == nullptr) return message("param_not_catalogued", {std::to_string(number)});
    // The words are put together only for a refusal: a machine folder's every parameter is checked.
    auto refusal = [&](std::string_view id, std::vector<std::string> rule) {
        std::vector<std::string> arguments{std::to_string(number), bilingual(p->nameEn, p->nameZh)};
        arguments.insert(arguments.end(), rule.begin(), rule.end());
        arguments.push_back(formatNumber(value));
        return message(id, std::move(arguments));
    };
    switch (p->type) {
    case ParameterInfo::Type::Int:
        // Written as negations so that NaN is refused too.
        if (!(value == std::floor(value) && value >= p->min && value <= p->max))
            return refusal("param_must_be_whole", {formatNumber(p->min), formatNumber(p->max)});
        return std::nullopt;
    case ParameterInfo::Type::Real:
        if (!(value >= p->min && value <= p->max)) return refusal("param_must_be_in_range", {formatNumber(p->min), formatNumber(p->max)});
        return std::nullopt;
    case ParameterInfo::Type::Select:
        break;
    }
    std::string english;
    std::string chinese;
    for (const ParameterOption& option : p->options) {
        if (option.value == value) return std::nullopt;
        english += (english.empty() ? "" : ", ") + formatNumber(option.value) + " (" + option.en + ")";
        chinese += (chinese.empty() ? "" : "、") + formatNumber(option.value) + "（" + option.zh + "）";
    }
    return refusal("param_must_be_one_of", {bilingual(english, chinese)});
}

double ParameterCatalogue::atResolution(int number, double value) const {
    const ParameterInfo* p = find(number);
    if (p == nullptr || !std::isfinite(value)) {
        return value;
    }
    // scaled by a whole number and divided back: the nearest double to the decimal, which the
    // writer's shortest form then prints as it reads ("-48.12")
    const double scale = p->type == ParameterInfo::Type::Real ? 1e4 : 1.0;
    const double rounded = std::round(value * scale) / scale;
    return rounded == 0.0 ? 0.0 : rounded; // no -0
}

void ParameterCatalogue::applyDefaults(ParameterTable& table) const {
    for (const ParameterInfo& p : params_)
        if (ParameterTable::valid(p.number)) table.set(p.number, p.defaultValue);
}

} // namespace m350::params
