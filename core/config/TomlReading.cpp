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
               std::initializer_list<std::string_view> known, std::vector<std::string>& warnings) {
    for (auto&& [key, value] : table) {
        const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
        if (isKnown(known, prefix + ".*")) {
            continue;
        }
        if (!isKnown(known, path)) {
            warnings.push_back(warningAt(file, key.source(), "unknown key '" + path + "' (ignored; a typo?)"));
            continue;
        }
        if (const toml::table* inner = value.as_table()) {
            checkKeys(file, *inner, path, known, warnings);
        } else if (const toml::array* entries = value.as_array(); entries && entries->is_array_of_tables()) {
            for (const toml::node& entry : *entries) {
                checkKeys(file, *entry.as_table(), path, known, warnings);
            }
        }
    }
}

} // namespace

std::string warningAt(const fs::path& file, const toml::source_region& where, const std::string& message) {
    return file.string() + ":" + placed(where) + ": warning: " + message;
}

void fail(const fs::path& file, std::string message, const toml::source_region& where) {
    ConfigError error{file.string(), std::move(message)};
    error.line = static_cast<int>(where.begin.line);
    error.column = static_cast<int>(where.begin.column);
    throw Failure{std::move(error)};
}

toml::table parseToml(const fs::path& file) {
    try {
        return files::parseTomlFile(file.string());
    } catch (const toml::parse_error& e) {
        fail(file, std::string(e.description()), e.source());
    }
}

int numberKey(const fs::path& file, std::string_view text, const toml::source_region& where, int low, int high,
              const char* what) {
    int n = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || ptr != text.data() + text.size() || n < low || n > high) {
        fail(file,
             std::string(what) + " '" + std::string(text) + "' is not a number from " + std::to_string(low) + " to " +
                 std::to_string(high),
             where);
    }
    return n;
}

double numberValue(const fs::path& file, const toml::node& node, std::string_view key) {
    if (auto v = node.value<double>()) {
        if (!std::isfinite(*v)) {
            fail(file,
                 "'" + std::string(key) + "' must be a finite number, not " + (std::isnan(*v) ? "nan" : "inf"),
                 node.source());
        }
        return *v;
    }
    fail(file, "'" + std::string(key) + "' must be a number", node.source());
}

int wholeValue(const fs::path& file, const toml::table& table, std::string_view key, int low, int high, int fallback) {
    const toml::node* node = table.get(key);
    if (!node) {
        return fallback;
    }
    auto v = node->value_exact<std::int64_t>();
    if (!v || *v < low || *v > high) {
        fail(file,
             "'" + std::string(key) + "' must be a whole number from " + std::to_string(low) + " to " +
                 std::to_string(high),
             node->source());
    }
    return static_cast<int>(*v);
}

void warnUnknownKeys(const fs::path& file, const toml::table& table, std::initializer_list<std::string_view> known,
                     std::vector<std::string>& warnings) {
    checkKeys(file, table, "", known, warnings);
}

} // namespace m350::config::toml_reading
