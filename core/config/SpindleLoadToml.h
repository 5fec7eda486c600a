#pragma once

#include "core/machine/SpindleLoadModel.h"

#include "core/files/Toml.h"

#include <filesystem>
#include <optional>

namespace m350::config {

// Reads machine.toml's [stock] (top = machine Z of the work's top face for the tool tip, x and y =
// [min, max], unbounded when left out) and [spindle_load] (idle, per_krpm, per_cm3,
// spike_factor, spike_ms; lambda is parameter 4127 in params.toml): the simulated world the spindle load comes from.
// `out` stays empty when the file has neither; a bad value fails with file:line:col.
void readSpindleLoadWorld(const std::filesystem::path& file, const toml::table& machine,
                          std::optional<machine::SpindleLoadModel>& out);

} // namespace m350::config
