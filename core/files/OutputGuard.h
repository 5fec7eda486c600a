#pragma once

#include "core/common/Message.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace m350::files {

// What a program reads or owns and so never writes an output over: an input file (the program, a
// library, a replay being played), or a whole folder (the panel's machine folder).
struct GuardedPath {
    std::string what; // "the program of this run", "the replay being played": in both languages (bilingual())
    std::filesystem::path path;
    bool folder = false; // nothing inside it either (a new file included)
};

// An output that would land on a guarded path: which one, and whether inside its folder.
struct GuardHit {
    GuardedPath guarded;
    bool inside = false; // inside a guarded folder (else the same file as a guarded input)
};

// Whether `output` lands on a guarded path: the same file as a guarded input (through any link or
// `..`), or anything inside a guarded folder. Asked before anything is opened: `--trace prog.nc`
// once emptied the program. m350-sim and m350-hmi both ask it.
std::optional<GuardHit> outputOverGuarded(const std::filesystem::path& output, const std::vector<GuardedPath>& guarded);
// The same, as the command lines say it: "--trace prog.nc is the program of this run (prog.nc):
// refused, nothing was written", by message id (`option` may be bilingual too).
std::optional<Message> refusedOutput(const std::string& option, const std::filesystem::path& output,
                                         const std::vector<GuardedPath>& guarded);

// Why `output` cannot be an output file at all, said before a run rather than after it.
enum class Unwritable { Folder, Socket, BlockDevice, NoFolder, ParentNotFolder };
// nullopt for a regular file (replaced whole, atomically), a new file in an existing folder, a FIFO
// or a character device (written as a device, never replaced).
std::optional<Unwritable> unwritableOutput(const std::filesystem::path& output);
// "--state notes.txt/s.json: notes.txt is not a folder: refused, nothing was written"
// (by message id; `option` may be bilingual())
Message describeUnwritable(const std::string& option, const std::filesystem::path& output, Unwritable why);

} // namespace m350::files
