#pragma once

#include "core/common/Message.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace m350::files {

// Points where a test may interrupt a write, as a crash or a killed process would.
struct AtomicWriteHooks {
    std::function<void(std::size_t written)> afterChunk; // after each chunk of the temp file
    std::function<void()> beforeRename;                  // the temp file is complete and synced
    // files::writeTogether only: after one of its files is in place and before the next is
    std::function<void()> betweenFiles;
};

// Replaces `path` with `content` so that a reader (or the next start after a crash) sees either
// the old file or the new one, never a part: the bytes go to a temp file of this writer's own
// beside it (two writers never share one), which is synced, renamed over the target, and the folder
// is synced so the rename itself survives a power cut. The target keeps its permissions. Temp files
// that killed writers left for the same target are removed afterwards. nullopt on success, else
// why (naming the file), by message id.
std::optional<Message> writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                                               const AtomicWriteHooks& hooks = {});

// Syncs a folder, so that a rename or a new file in it survives a power cut. nullopt on success.
std::optional<Message> syncFolder(const std::filesystem::path& folder);

// A new, empty temp file beside `target` for one writer: `.NAME.PID.XXXXXX` (hidden, so no reader
// of the folder takes it for a file of its own), created with `mode`. Its open descriptor and path,
// or why not.
struct TempFile {
    int descriptor = -1;
    std::filesystem::path path;
};
std::variant<TempFile, Message> createTempBeside(const std::filesystem::path& target, unsigned mode);

// The temp files beside `target` whose writer is gone (killed mid-write): the ones a later
// successful write removes.
std::vector<std::filesystem::path> staleTempFiles(const std::filesystem::path& target);

} // namespace m350::files
