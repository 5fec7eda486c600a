#pragma once

// How the machine folder's TOML files are read: every refusal names file:line:col, every file is
// read with a size cap, and keys nobody reads (typos) are warned about.
#include "core/config/MachineConfig.h"

#include "core/files/Toml.h"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace m350::config::toml_reading {

// Thrown by fail(); loadMachineFolder turns it into its ConfigError.
struct Failure {
    ConfigError error;
};

[[noreturn]] void fail(const std::filesystem::path& file, Message message, const toml::source_region& where = {});

// The file parsed; refused when it is not a regular file or larger than a machine file can be.
toml::table parseToml(const std::filesystem::path& file);

// "file:line:col: warning: message", as the loaders list what they kept but doubt.
Message warningAt(const std::filesystem::path& file, const toml::source_region& where, const Message& words);
// "file:line:col", where a setting stands, for messages that name it.
std::string settingPlace(const std::filesystem::path& file, const toml::source_region& where);
// "file: warning: message": a doubt about the whole file.
Message warningIn(const std::filesystem::path& file, const Message& words);

// A table key that must be a whole number low..high (parameter, variable, reference point numbers).
// `what` names the key in both languages (bilingual(): "parameter", 参数).
int numberKey(const std::filesystem::path& file, std::string_view text, const toml::source_region& where, int low,
              int high, const std::string& what);

// A finite number: nan or inf as a position, feed or time would stop virtual time advancing.
double numberValue(const std::filesystem::path& file, const toml::node& node, std::string_view key);

// A whole number low..high, or `fallback` when the key is absent.
int wholeValue(const std::filesystem::path& file, const toml::table& table, std::string_view key, int low, int high,
               int fallback);

// "file:line:col: warning: unknown key ..." for each key of `table` not in `known`. Known names are
// dotted paths ("magazine.device"); "codes.*" accepts any key under [codes]; an array of tables
// ("io_links") is checked entry by entry.
void warnUnknownKeys(const std::filesystem::path& file, const toml::table& table,
                     std::initializer_list<std::string_view> known, MachineConfig& config);

} // namespace m350::config::toml_reading
