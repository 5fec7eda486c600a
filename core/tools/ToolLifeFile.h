#pragma once

#include "core/tools/ToolLifeData.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace m350::tools {

// The machine folder's tool life file, toollife.txt: the FANUC settings and the groups with their
// sister tools and the life each has used, one item a line, `;` starts a comment:
//   gs 0              GS2 * 2 + GS1 (parameter 6800 #0 #1): 0 = 16 groups x 16 tools ... 3 = 128 x 2
//   ignore 100        parameter 6810, the tool life management ignore number (T101 = group 1)
//   ltm count         parameter 6800 #2: the kind of a group G10 L3 enters without Q (count|minutes)
//   group 1 life 100 count
//   tool 12 h 12 d 32 used 5        uses, or cutting time in 4 s units for a minutes group
inline constexpr const char* kToolLifeFile = "toollife.txt";

struct LifeFileError {
    std::string file;
    std::uint32_t line = 0;
    std::string message;
    std::string text() const { return file + ":" + std::to_string(line) + ": " + message; }
};

// The whole text is checked: any bad line is an error naming it, and no data are taken.
std::variant<LifeData, LifeFileError> parseToolLife(std::string_view text, const std::string& file);
// No file is no groups.
std::variant<LifeData, LifeFileError> loadToolLife(const std::string& folder);
std::string formatToolLife(const LifeData& data);
// Written atomically (temp file, sync, rename); the reason when it cannot be.
std::optional<std::string> saveToolLife(const std::string& folder, const LifeData& data);

} // namespace m350::tools
