#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace m350::config {

// Points where a test may interrupt a write, as a crash or a killed process would.
struct AtomicWriteHooks {
    std::function<void(std::size_t written)> afterChunk; // after each chunk of the temp file
    std::function<void()> beforeRename;                  // the temp file is complete and synced
};

// Replaces `path` with `content` so that a reader (or the next start after a crash) sees either
// the old file or the new one, never a part: the bytes go to a temp file beside it, which is
// synced, renamed over the target, and the folder is synced so the rename itself survives a
// power cut. The target keeps its permissions. nullopt on success, else why (naming the file).
std::optional<std::string> writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                                               const AtomicWriteHooks& hooks = {});

// Syncs a folder, so that a rename or a new file in it survives a power cut. nullopt on success.
std::optional<std::string> syncFolder(const std::filesystem::path& folder);

// The temp file writeFileAtomically uses for `path` (left behind only by a process killed mid-write;
// the next write replaces it).
std::filesystem::path atomicTempPath(const std::filesystem::path& path);

} // namespace m350::config
