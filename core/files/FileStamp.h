#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace m350::files {

// What stat says of a file that changes whenever its content can have changed: the file itself
// (device, inode: a file renamed over it is another), its size, and its modification and change
// times. The change time (ctime) cannot be set back by a user (touch -d sets mtime alone), so an
// edit that keeps the size and the time stamp still shows. Two edits inside one tick of the file
// system's clock can share a ctime: a stamp is `settled` only when its ctime lies well before the
// moment it was taken (as git trusts its index only for files older than the index), and only a
// settled stamp may stand for the content it was taken with.
struct FileStamp {
    bool exists = false;
    std::uint64_t device = 0;
    std::uint64_t inode = 0;
    std::int64_t size = 0;
    std::int64_t modifiedNs = 0;
    std::int64_t changedNs = 0;
    bool settled = false;

    // How long before the stamp's taking its ctime must lie to be settled.
    static constexpr std::chrono::seconds kSettle{2};

    // `path`'s stamp (links followed), taken at `now` (the wall clock, before the stat).
    static FileStamp of(const std::string& path, std::chrono::system_clock::time_point now);
    // The same file with the same content as far as stat can tell (settled aside).
    bool sameFile(const FileStamp& other) const {
        return exists && other.exists && device == other.device && inode == other.inode && size == other.size &&
               modifiedNs == other.modifiedNs && changedNs == other.changedNs;
    }
};

} // namespace m350::files
