#pragma once

#include "core/machine/ToolWorld.h"
#include "core/tools/SpindleLoadLimits.h"

#include <string>
#include <utility>

namespace m350::sim {

// `--break T1=0.62` (broken before the run) or `T1=0.62@4.5` (at 4.5 s of virtual time).
// Throws CLI::ValidationError saying what is wrong.
machine::ToolBreak parseToolBreak(const std::string& item);
// `--load-limits T1=8:60`: the lower and upper spindle load % of tool 1 (upper 0: none).
std::pair<int, tools::LoadLimits> parseLoadLimits(const std::string& item);

} // namespace m350::sim
