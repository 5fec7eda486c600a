#include "core/files/ScratchFolder.h"

#include <unistd.h>

#include <algorithm>
#include <mutex>

namespace fs = std::filesystem;

namespace m350::files {

namespace {

std::mutex scratchMutex;
fs::path scratch; // absolute, normal form; empty: none

fs::path normalAbsolute(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal();
}

} // namespace

void setScratchFolder(const fs::path& folder) {
    const std::lock_guard lock(scratchMutex);
    scratch = folder.empty() ? fs::path() : normalAbsolute(folder);
}

bool inScratchFolder(const fs::path& path) {
    const std::lock_guard lock(scratchMutex);
    if (scratch.empty()) {
        return false;
    }
    const fs::path candidate = normalAbsolute(path);
    auto [scratchEnd, candidateAt] = std::mismatch(scratch.begin(), scratch.end(), candidate.begin(), candidate.end());
    // the folder itself or anything under it (a trailing "" element of "dir/" matches too)
    return scratchEnd == scratch.end() || (std::next(scratchEnd) == scratch.end() && scratchEnd->empty());
}

bool syncUnlessScratch(int fd, const fs::path& path) { return inScratchFolder(path) || ::fsync(fd) == 0; }

} // namespace m350::files
