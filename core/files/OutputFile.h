#pragma once

#include "core/common/Message.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace m350::files {

// A file a run writes as its result (the trace, DPRNT output, the tool table after the run). It is
// written to a temp file of its own beside the target and renamed over the target once complete,
// so runs writing one file at once leave one whole file (the last), never interleaved lines, and a
// run that fails to write leaves the old file. A target that exists and is not a regular file
// (/dev/null, /dev/stdout, a FIFO) is written directly. A link is written through: the file it
// leads to is replaced and the link stays. Every write error is reported.
class OutputFile {
public:
    // The file opened for writing, or why not (naming the file), by message id.
    static std::variant<std::unique_ptr<OutputFile>, Message> open(const std::filesystem::path& target);
    ~OutputFile(); // removes the temp file unless commit() succeeded
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& stream() { return stream_; }
    // Flushes, syncs and renames the temp file over the target; nullopt on success, else why.
    std::optional<Message> commit();

    // Where writing `target` goes: the file a link leads to (the link stays), else the target.
    static std::filesystem::path writtenPath(const std::filesystem::path& target);

private:
    OutputFile(std::filesystem::path target, std::filesystem::path temp);
    std::filesystem::path target_;
    std::filesystem::path temp_; // empty when the target is written directly
    std::ofstream stream_;
    bool committed_ = false;
};

// Writes `content` as one OutputFile; nullopt on success, else why.
std::optional<Message> writeOutputFile(const std::filesystem::path& target, std::string_view content);

} // namespace m350::files
