#pragma once

#include "core/files/AtomicFile.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace m350::files {

// One file of a change written by writeTogether.
struct ChangedFile {
    std::filesystem::path path;
    std::string_view content;
    bool keepLastGood = false; // also its NAME.last-good copy (files::saveKeepingLastGood)
};

// Writes several files of one folder as one change: a crash (kill -9, power cut) at any point
// leaves all of them old or all new, never a mix. Each new content goes to NAME.pending (synced);
// then `journal` is written atomically, naming each file with its size and checksum: that rename
// is the moment the change happens. The pending files are then renamed into place and the journal
// removed. A change a crash interrupted is finished (or dropped, before its journal) by
// finishInterruptedChange, which writeTogether also calls first. `hooks` interrupt the journal's
// write (before the change) and come between the files (after it). nullopt on success, else why.
std::optional<Message> writeTogether(const std::filesystem::path& journal, std::span<const ChangedFile> files,
                                         const AtomicWriteHooks& hooks = {});

// After a crash: with a whole journal, the pending files it names are renamed into place (each
// checked against its size and checksum) and the journal removed; without one, the `candidates`'
// NAME.pending files, left by a change that never happened, are removed. Nothing to do is one stat.
// nullopt when the folder is whole again, else why (naming the file).
std::optional<Message> finishInterruptedChange(const std::filesystem::path& journal,
                                                   std::span<const std::filesystem::path> candidates);

// NAME.pending beside `file`: where writeTogether puts its new content until the change happens.
std::filesystem::path pendingPath(const std::filesystem::path& file);

} // namespace m350::files
