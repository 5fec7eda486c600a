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

std::variant<ParameterRestore, Message> readParameterBackup(const std::filesystem::path& file,
                                                            const ParameterCatalogue& catalogue) {
    toml::table t;
    try {
        t = files::parseTomlFile(file.string());
    } catch (const toml::parse_error& e) {
        return message("backup_file_toml", {where(file, e.source()), std::string(e.description())});
    }
    const toml::node* format = t.at_path("backup.format").node();
    if (!format || format->value<int>() != kFormat) {
        return message("backup_file_not_backup", {file.string()});
    }
    const toml::table* params = t["params"].as_table();
    if (!params) {
        return message("backup_file_no_params", {file.string()});
    }
    ParameterRestore restore;
    for (auto&& [key, node] : *params) {
        int n = -1;
        auto [end, ec] = std::from_chars(key.str().data(), key.str().data() + key.str().size(), n);
        if (ec != std::errc() || end != key.str().data() + key.str().size() || !ParameterTable::valid(n)) {
            return message("backup_file_bad_key", {where(file, key.source()), std::string(key.str())});
        }
        auto value = node.value<double>();
        if (!value || !std::isfinite(*value)) {
            return message("backup_file_not_finite", {where(file, node.source()), std::to_string(n)});
        }
        if (catalogue.find(n))
            if (auto problem = catalogue.validate(n, *value)) restore.outOfRange.push_back(problem->english());
        restore.values[n] = *value;
    }
    if (restore.values.size() != static_cast<std::size_t>(ParameterTable::kCount)) {
        return message("backup_file_count", {file.string(), std::to_string(restore.values.size())});
    }
    return restore;
}

} // namespace m350::params
