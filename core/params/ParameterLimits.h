#pragma once

#include "core/common/Message.h"
#include "core/params/ParameterTable.h"

#include <optional>
#include <string>

namespace m350::params {

// The most pockets (tools) any simulated magazine has: far above the M350's 20 and the FANUC
// carousels', low enough that a table of every pocket stays small.
inline constexpr int kMostPockets = 999;

// Values refused outright, wherever they come from (params.toml, --param, the panel), because they
// size what the simulator allocates or loops over: a magazine capacity of 1e9 allocated for
// minutes. Other out-of-range values are only warned about (see ParameterCatalogue::validate).
std::optional<Message> refusedParameterValue(int number, double value);

// Parameter 801 as a pocket count: what the tables of pockets are built from, whatever was set.
int magazineCapacity(const ParameterTable& parameters);

} // namespace m350::params
