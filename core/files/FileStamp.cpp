#include "core/files/FileStamp.h"

#include <sys/stat.h>

namespace m350::files {

namespace {

std::int64_t nanoseconds(const timespec& time) {
    return static_cast<std::int64_t>(time.tv_sec) * 1'000'000'000 + static_cast<std::int64_t>(time.tv_nsec);
}

} // namespace

FileStamp FileStamp::of(const std::string& path, std::chrono::system_clock::time_point now) {
    struct stat info {};
    FileStamp stamp;
    if (::stat(path.c_str(), &info) != 0) {
        return stamp;
    }
    stamp.exists = true;
    stamp.device = static_cast<std::uint64_t>(info.st_dev);
    stamp.inode = static_cast<std::uint64_t>(info.st_ino);
    stamp.size = static_cast<std::int64_t>(info.st_size);
    stamp.modifiedNs = nanoseconds(info.st_mtim);
    stamp.changedNs = nanoseconds(info.st_ctim);
    const std::int64_t settledBefore =
        std::chrono::duration_cast<std::chrono::nanoseconds>((now - kSettle).time_since_epoch()).count();
    stamp.settled = stamp.changedNs < settledBefore && stamp.modifiedNs < settledBefore;
    return stamp;
}

} // namespace m350::files
