#pragma once

#include <filesystem>

namespace m350::files {

// A folder whose files need not survive a power cut: m350-hmi's private copy of the bundled machine
// for a headless run (a replay, a screenshot), deleted when it exits. What is written inside it is
// not fsynced (nor is the folder after a rename): a replay of many MDI lines spent most of its wall
// time in fsync, protecting files nobody keeps. Every other file is synced as before. Empty: none.
void setScratchFolder(const std::filesystem::path& folder);
bool inScratchFolder(const std::filesystem::path& path);

// fsync(fd), unless `path` is in the scratch folder; true when done (or not needed).
bool syncUnlessScratch(int fd, const std::filesystem::path& path);

} // namespace m350::files
