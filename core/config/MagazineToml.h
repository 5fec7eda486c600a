#pragma once

#include "core/common/Message.h"
#include "core/config/MagazineConfig.h"

#include "core/files/Toml.h"

#include <optional>
#include <string>

namespace m350::config {

// Reads the [magazine] table of machine.toml into `out`; what is wrong with it, if anything.
std::optional<Message> readMagazine(const toml::table& magazine, MagazineConfig& out);

} // namespace m350::config
