#pragma once

#include "core/tools/ToolLifeManager.h"

#include <nlohmann/json.hpp>

namespace m350::sim {

// The run JSON's "tool_life" (only on machines with tool life groups): the ignore number, the tool
// in use and each group's tools with what they used ("used" in uses or 4 s units, "life" likewise).
nlohmann::json toolLifeJson(const tools::ToolLifeManager& manager);

} // namespace m350::sim
