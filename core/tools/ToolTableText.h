#pragma once

#include "core/tools/ToolTable.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m350::tools {

// The pieces of tool.tbl text that the reader, the writer and the panel share.

// A tool table number: optional sign (LinuxCNC writes `+0.500000`), digits with an optional point,
// an optional exponent; finite. nullopt for anything else ("0x10", "nan", "", "1.2.3").
std::optional<double> parseTableNumber(std::string_view text);
// The same, holding a whole number that fits an int ("3", "+3", "3.0").
std::optional<int> parseWholeNumber(std::string_view text);
// The shortest text that reads back as the same double: "66.323", "-0.5", "1e-07".
std::string tableNumber(double value);

// A comment split into its text and the extras group at its end: `6 mm {rpm=24000 teeth=2}`.
// A trailing `{...}` whose items all look like key=value is the group; an unknown key, a bad value
// or a key given twice is a problem (with its 1-based column, counted from `firstColumn` for the
// comment's first character) and then the whole comment stays `text`, extras unset.
struct CommentProblem {
    int column = 0;
    std::string message;
};
struct CommentParts {
    std::string text;
    std::optional<double> maxRpm;
    std::optional<int> teeth;
    std::optional<ToolType> type;
    std::optional<double> lengthWear;
    std::optional<double> radiusWear;
    std::vector<CommentProblem> problems;
};
CommentParts splitComment(std::string_view comment, int firstColumn);
// The comment as written back: the text, then the extras group when the entry has extras.
std::string joinComment(const ToolEntry& entry);

} // namespace m350::tools
