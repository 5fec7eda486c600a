#include "app/sim/BreakageOptions.h"
#include "app/sim/UsageError.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>

namespace m350::sim {

namespace {

double number(const std::string& text, const std::string& item, const char* option) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v)) {
        throw UsageError(option, message("usage_item_not_number", {item, text}));
    }
    return v;
}

// "T1=rest" -> (1, "rest")
std::pair<int, std::string> toolAndValue(const std::string& item, const char* option, const std::string& example) {
    auto eq = item.find('=');
    if (eq == std::string::npos || eq < 2 || (item[0] != 'T' && item[0] != 't') || eq + 1 == item.size()) {
        throw UsageError(option, message("usage_looks_like", {item, example}));
    }
    double tool = number(item.substr(1, eq - 1), item, option);
    if (tool < 1 || tool > 9999 || tool != std::trunc(tool)) {
        throw UsageError(option, message("usage_tools_range", {item}));
    }
    return {static_cast<int>(tool), item.substr(eq + 1)};
}

} // namespace

machine::ToolBreak parseToolBreak(const std::string& item) {
    auto [tool, rest] = toolAndValue(item, "--break", bilingual("T1=0.62 or T1=0.62@4.5", "T1=0.62或T1=0.62@4.5"));
    auto at = rest.find('@');
    machine::ToolBreak broken;
    broken.tool = tool;
    broken.shortBy = number(rest.substr(0, at), item, "--break");
    broken.at = at == std::string::npos ? 0.0 : number(rest.substr(at + 1), item, "--break");
    if (broken.shortBy <= 0.0 || broken.at < 0.0) {
        throw UsageError("--break", message("usage_break_values", {item}));
    }
    return broken;
}

std::pair<int, tools::LoadLimits> parseLoadLimits(const std::string& item) {
    const std::string example = bilingual("T1=8:60 (lower:upper load %)", "T1=8:60（负载下限:上限 %）");
    auto [tool, rest] = toolAndValue(item, "--load-limits", example);
    auto colon = rest.find(':');
    if (colon == std::string::npos) {
        throw UsageError("--load-limits", message("usage_looks_like", {item, example}));
    }
    tools::LoadLimits limits;
    limits.lower = number(rest.substr(0, colon), item, "--load-limits");
    limits.upper = number(rest.substr(colon + 1), item, "--load-limits");
    if (limits.lower < 0.0 || limits.upper < 0.0 || (limits.upper > 0.0 && limits.upper <= limits.lower)) {
        throw UsageError("--load-limits", message("usage_load_limits", {item}));
    }
    return {tool, limits};
}

} // namespace m350::sim
