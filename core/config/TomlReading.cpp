#include "core/config/TomlReading.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace m350::config::toml_reading {

namespace fs = std::filesystem;

namespace {

std::string placed(const toml::source_region& where) {
    return std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

bool isKnown(std::initializer_list<std::string_view> known, const std::string& path) {
    return std::find(known.begin(), known.end(), path) != known.end();
}

void checkKeys(const fs::path& file, const toml::table& table, const std::string& prefix,
               std::initializer_list<std::string_view> known, MachineConfig& config) {
    for (auto&& [key, value] : table) {
        const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
        if (isKnown(known, prefix + ".*")) {
            continue;
        }
        if (!isKnown(known, path)) {
            config.warn(warningAt(file, key.source(), message("config_unknown_key", {path})));
            continue;
        }
        if (const toml::table* inner = value.as_table()) {
            checkKeys(file, *inner, path, known, config);
        } else if (const toml::array* entries = value.as_array(); entries && entries->is_array_of_tables()) {
            for (const toml::node& entry : *entries) {
                checkKeys(file, *entry.as_table(), path, known, config);
            }
        }
    }
}

} // namespace

Message warningAt(const fs::path& file, const toml::source_region& where, const Message& words) {
    return message("config_warning_at", {file.string() + ":" + placed(where), bilingual(words)});
}

std::string settingPlace(const fs::path& file, const toml::source_region& where) {
    return file.string() + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

Message warningIn(const fs::path& file, const Message& words) {
    return message("config_warning_at", {file.string(), bilingual(words)});
}

void fail(const fs::path& file, Message message, const toml::source_region& where) {
    ConfigError error{file.string(), std::move(message)};
    error.line = static_cast<int>(where.begin.line);
    error.column = static_cast<int>(where.begin.column);
    throw Failure{std::move(error)};
}

toml::table parseToml(const fs::path& file) {
    try {
        return files::parseTomlFile(file.string());
    } catch (const files::UnreadableToml& e) {
        fail(file, e.why(), e.source());
    } catch (const toml::parse_error& e) {
        fail(file, message("config_toml_syntax", {std::string(e.description())}), e.source());
    }
}

int numberKey(const fs::path& file, std::string_view text, const toml::source_region& where, int low, int high,
              const std::string& what) {
    int n = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || ptr != text.data() + text.size() || n < low || n > high) {
        fail(file, message("config_number_key", {what, std::string(text), std::to_string(low), std::to_string(high)}),
             where);
    }
    return n;
}

double numberValue(const fs::path& file, const toml::node& node, std::string_view key) {
    if (auto v = node.value<double>()) {
        if (!std::isfinite(*v)) {
            fail(file, message("config_must_be_finite", {std::string(key), std::isnan(*v) ? "nan" : "inf"}), node.source());
        }
        return *v;
    }
    fail(file, message("config_must_be_number", {std::string(key)}), node.source());
}

int wholeValue(const fs::path& file, const toml::table& table, std::string_view key, int low, int high, int fallback) {
    const toml::node* node = table.get(key);
    if (!node) {
        return fallback;
    }
    auto v = node->value_exact<std::int64_t>();
    if (!v || *v < low || *v > high) {
        fail(file, message("config_must_be_whole", {std::string(key), std::to_string(low), std::to_string(high)}),
             node->source());
    }
    return static_cast<int>(*v);
}

void warnUnknownKeys(const fs::path& file, const toml::table& table, std::initializer_list<std::string_view> known,
                     MachineConfig& config) {
    checkKeys(file, table, "", known, config);
}

} // namespace m350::config::toml_reading
