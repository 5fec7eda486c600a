#pragma once

#include "core/common/Message.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace m350::files {

// Far above any real machine file (a 100,000-tool table is a few MB); a huge file named as one is
// refused, not read.
constexpr std::uintmax_t kMostMachineFileBytes = 16 * 1024 * 1024;

// The one check every file of a machine folder passes before it is read: a FIFO would block the
// reader forever, a link to /dev/zero (or any device) would be read until memory runs out, so only
// a regular file of at most `mostBytes` is read, and it is read with that bound even if it grows
// meanwhile. Fills `text` and returns nullopt, or says why not, without the path ("it is a FIFO
// (named pipe), not a regular file", the OS's "No such file or directory", "20 MiB is more than
// ..."), by message id.
std::optional<Message> readMachineFile(const std::filesystem::path& file, std::string& text,
                                           std::uintmax_t mostBytes = kMostMachineFileBytes);

} // namespace m350::files
