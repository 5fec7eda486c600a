#pragma once

#include "core/tools/ToolLifeFile.h"
#include "core/tools/ToolLifeManager.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace m350::sim {

// The run JSON's "tool_life" (on machines with tool life groups, or whose toollife.txt had lines
// skipped): the ignore number, the tool in use, each group's tools with what they used and have
// left ("used", "remaining" and "life_units" in uses or 4 s units) and whether each is in use or
// expired, and "issues": the skipped lines of toollife.txt with file, line, column and message.
nlohmann::json toolLifeJson(const tools::ToolLifeManager& manager, const std::vector<tools::LifeFileIssue>& issues);

} // namespace m350::sim
