#pragma once

#include "core/files/AtomicFile.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace m350::files {

// A machine folder's files that the simulator writes (params.toml, tool.tbl, toollife.txt) keep
// their last good state beside them as NAME.last-good: written with each save and refreshed when
// the folder loads the file cleanly, so a file broken by hand (or by another program) can be put
// back; the loader's error names the copy.
std::filesystem::path lastGoodPath(const std::filesystem::path& file);

// Writes `content` into `file` atomically, then the same into its last good copy. nullopt on
// success, else why; a copy that cannot be written fails the save too (the folder is read-only or full).
std::optional<Message> saveKeepingLastGood(const std::filesystem::path& file, std::string_view content,
                                               const AtomicWriteHooks& hooks = {});

// After `file` loaded cleanly: an existing last good copy that differs from it is replaced. Nothing
// happens where no copy exists (a folder the simulator never saved into, such as a bundled one).
void refreshLastGood(const std::filesystem::path& file);

// " (its last good copy: PATH)" when `file` has one, else "": for the message that says it is broken.
std::string lastGoodNote(const std::filesystem::path& file);

} // namespace m350::files
