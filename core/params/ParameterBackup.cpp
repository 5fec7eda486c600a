#include "core/params/ParameterBackup.h"

#include "core/params/ParamsFileWriter.h"

#include "core/files/Toml.h"

#include <charconv>
#include <cmath>

namespace m350::params {

namespace {

constexpr int kFormat = 1;

std::string where(const std::filesystem::path& file, const toml::source_region& at) {
    return file.string() + ":" + std::to_string(at.begin.line) + ":" + std::to_string(at.begin.column) + ": ";
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

} // namespace

std::string formatParameterBackup(const ParameterTable& parameters, const ParameterCatalogue& catalogue,
                                  const std::string& machineName) {
    std::string out = "# M350 Studio parameter backup (参数备份): every parameter 0-999, read by 参数恢复\n";
    out += "[backup]\nmachine = " + quoted(machineName) + "\nformat = " + std::to_string(kFormat) + "\n\n[params]\n";
    for (int n = 0; n < ParameterTable::kCount; ++n) {
        out += std::to_string(n) + " = " + tomlNumber(parameters.get(n));
        if (const ParameterInfo* info = catalogue.find(n)) out += "  # " + info->nameZh + " " + info->nameEn;
        out += '\n';
    }
    return out;
}

std::variant<ParameterRestore, std::string> readParameterBackup(const std::filesystem::path& file,
                                                                const ParameterCatalogue& catalogue) {
    toml::table t;
    try {
        t = files::parseTomlFile(file.string());
    } catch (const toml::parse_error& e) {
        return where(file, e.source()) + std::string(e.description());
    }
    const toml::node* format = t.at_path("backup.format").node();
    if (!format || format->value<int>() != kFormat)
        return file.string() + ":1:1: not a parameter backup (its [backup] table must say format = 1)";
    const toml::table* params = t["params"].as_table();
    if (!params) return file.string() + ":1:1: no [params] table";
    ParameterRestore restore;
    for (auto&& [key, node] : *params) {
        int n = -1;
        auto [end, ec] = std::from_chars(key.str().data(), key.str().data() + key.str().size(), n);
        if (ec != std::errc() || end != key.str().data() + key.str().size() || !ParameterTable::valid(n))
            return where(file, key.source()) + "'" + std::string(key.str()) + "' is not a parameter from 0 to 999";
        auto value = node.value<double>();
        if (!value || !std::isfinite(*value)) return where(file, node.source()) + "parameter " + std::to_string(n) + " must be a finite number";
        if (catalogue.find(n))
            if (auto problem = catalogue.validate(n, *value)) restore.outOfRange.push_back(problem->english());
        restore.values[n] = *value;
    }
    if (restore.values.size() != static_cast<std::size_t>(ParameterTable::kCount))
        return file.string() + ": holds " + std::to_string(restore.values.size()) +
               " parameters; a backup holds all 1000 (0-999)";
    return restore;
}

} // namespace m350::params
