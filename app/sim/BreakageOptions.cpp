#include "app/sim/BreakageOptions.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>

namespace m350::sim {

namespace {

double number(const std::string& text, const std::string& item, const char* option) {
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v)) {
        throw CLI::ValidationError(option, "'" + item + "': '" + text + "' is not a number");
    }
    return v;
}

// "T1=rest" -> (1, "rest")
std::pair<int, std::string> toolAndValue(const std::string& item, const char* option, const char* example) {
    auto eq = item.find('=');
    if (eq == std::string::npos || eq < 2 || (item[0] != 'T' && item[0] != 't') || eq + 1 == item.size()) {
        throw CLI::ValidationError(option, "'" + item + "' must look like " + example);
    }
    double tool = number(item.substr(1, eq - 1), item, option);
    if (tool < 1 || tool > 9999 || tool != std::trunc(tool)) {
        throw CLI::ValidationError(option, "'" + item + "': tools are T1-T9999");
    }
    return {static_cast<int>(tool), item.substr(eq + 1)};
}

} // namespace

machine::ToolBreak parseToolBreak(const std::string& item) {
    auto [tool, rest] = toolAndValue(item, "--break", "T1=0.62 or T1=0.62@4.5");
    auto at = rest.find('@');
    machine::ToolBreak broken;
    broken.tool = tool;
    broken.shortBy = number(rest.substr(0, at), item, "--break");
    broken.at = at == std::string::npos ? 0.0 : number(rest.substr(at + 1), item, "--break");
    if (broken.shortBy <= 0.0 || broken.at < 0.0) {
        throw CLI::ValidationError("--break", "'" + item + "': the tool breaks off more than 0 mm, at 0 s or later");
    }
    return broken;
}

std::pair<int, tools::LoadLimits> parseLoadLimits(const std::string& item) {
    auto [tool, rest] = toolAndValue(item, "--load-limits", "T1=8:60 (lower:upper load %)");
    auto colon = rest.find(':');
    if (colon == std::string::npos) {
        throw CLI::ValidationError("--load-limits", "'" + item + "' must look like T1=8:60 (lower:upper load %)");
    }
    tools::LoadLimits limits;
    limits.lower = number(rest.substr(0, colon), item, "--load-limits");
    limits.upper = number(rest.substr(colon + 1), item, "--load-limits");
    if (limits.lower < 0.0 || limits.upper < 0.0 || (limits.upper > 0.0 && limits.upper <= limits.lower)) {
        throw CLI::ValidationError("--load-limits", "'" + item + "': need 0 <= lower < upper (upper 0: none)");
    }
    return {tool, limits};
}

} // namespace m350::sim
