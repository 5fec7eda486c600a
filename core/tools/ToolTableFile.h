#pragma once

#include "core/common/Message.h"
#include "core/tools/ToolTable.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::tools {

// LinuxCNC's tool.tbl, as its documentation describes it: one tool a line,
//   T<tool> P<pocket> [X Y Z A B C U V W <offset>] [D<diameter>] [I<front angle>] [J<back angle>]
//   [Q<orientation 0-9>] [;comment]
// words separated by spaces or tabs, in any order, each at most once; T and P required and unique
// in the file; a line starting with ';' is a comment; at most 1000 tools. Lower-case letters and a
// leading '+' (LinuxCNC writes `Z+0.500000`) are read too; an exponent is allowed.
// The reader is stricter than LinuxCNC's (which reads `Z0x10` as 16 and `Znan`): a line it cannot
// take exactly is reported with file:line:col and skipped (kept in the table as text, so saving
// does not delete it), and the other lines load. The extras group at the end of the comment,
// `{rpm=24000 teeth=2 type=flat}` (keys rpm, teeth, type; types: see toolTypeKey), is read into
// ToolEntry; a bad item there is a warning and the group stays plain comment text.
struct ToolTableIssue {
    enum class Severity { Error, Warning } severity = Severity::Error;
    std::string file;
    int line = 0;   // 1-based
    int column = 0; // 1-based
    std::string message;
    // > 0: this issue stands for that many left out (gcode::DiagnosticCap: a table of 100,000 bad
    // lines lists its first and last 500, as `check` does)
    std::uint64_t omitted = 0;
    Message words{}; // `message` by message id (core/common/Message.h), for the panel and `m350-sim --lang`
};
// "tool.tbl:3:7: error: ... (line skipped)" / "tool.tbl:4:30: warning: ..."
std::string formatIssue(const ToolTableIssue& issue, MessageLanguage language = MessageLanguage::English);

struct ParsedToolTable {
    ToolTable table;
    std::vector<ToolTableIssue> issues;
    bool skippedLines() const;
};

ParsedToolTable parseToolTable(std::string_view text, const std::string& fileName);

// A row as the writer puts it: `T1 P1 Z66.323 D6 ;end mill {rpm=24000 teeth=2 type=flat}`, the
// numbers in their shortest exact form.
std::string formatToolEntry(const ToolEntry& entry);
// The table in its order: untouched rows and other lines as read, changed rows as formatToolEntry.
std::string formatToolTable(const ToolTable& table);

// Reads and parses a file; the error (naming the file) when it cannot be read.
std::variant<ParsedToolTable, Message> readToolTableFile(const std::filesystem::path& path);

inline constexpr const char* kToolTableFileName = "tool.tbl";

} // namespace m350::tools
