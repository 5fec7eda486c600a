#pragma once

#include "core/tools/ToolLifeData.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::tools {

// The machine folder's tool life file, toollife.txt: the FANUC settings and the groups with their
// sister tools and the life each has used, one item a line, `;` starts a comment:
//   gs 0              GS2 * 2 + GS1 (parameter 6800 #0 #1): 0 = 16 groups x 16 tools ... 3 = 128 x 2
//   ignore 100        parameter 6810, the tool life management ignore number (T101 = group 1)
//   ltm count         parameter 6800 #2: the kind of a group G10 L3 enters without Q (count|minutes)
// (these three only on the M350, whose tool life is a simulator extra: a FANUC's are its parameters)
//   group 1 life 100 count
//   tool 12 h 12 d 32 used 5        uses, or cutting time in 4 s units for a minutes group
// A line the reader cannot take is reported with file:line:col and skipped; the rest loads. A
// group that ends up without tools, or beyond the GS1/GS2 capacity, is skipped with its tool
// lines. Skipped lines are kept (LifeData::unreadLines) and written back as `; not read: ...`
// comments, so that saving the data the controller counted deletes nothing the operator typed.
inline constexpr const char* kToolLifeFile = "toollife.txt";
inline constexpr std::string_view kUnreadPrefix = "; not read: ";

struct LifeFileIssue {
    std::string file;
    std::uint32_t line = 0;   // 1-based
    std::uint32_t column = 0; // 1-based
    std::string message; // English, as the JSON says it
    Message words;       // the same by message id
    // "toollife.txt:3:26: error: unknown word 'extra' (line skipped)"
    std::string text(MessageLanguage language = MessageLanguage::English) const;
};

struct ParsedToolLife {
    LifeData data;
    std::vector<LifeFileIssue> issues;
};

// `settings`: a FANUC machine's, from its parameters (LifeData::applyFanucParameters); the file's
// own gs / ignore / ltm lines are then refused as lines that belong in params.toml.
ParsedToolLife parseToolLife(std::string_view text, const std::string& file, const LifeData* settings = nullptr);
// No file is no groups; a file that cannot be read is an error (the message says what), since
// saving over it would lose it.
std::variant<ParsedToolLife, Message> loadToolLife(const std::string& folder, const LifeData* settings = nullptr);
std::string formatToolLife(const LifeData& data);
} // namespace m350::tools
