#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace m350::gcode {

// A program file mapped read-only into memory, so a large program is parsed where it lies. Another
// process may truncate the file while it is mapped; reading the lost pages would then raise
// SIGBUS and kill the simulator. While any file is mapped a SIGBUS handler puts zero-filled pages
// where the lost ones were, so the reader sees NUL bytes instead, and `truncated()` says so.
class MappedFile {
public:
    // The file mapped, or nothing when it cannot be (empty, not a regular file, no mmap): the
    // caller then reads it. Files up to kPopulateBytes are read in at once (fewer page faults);
    // larger ones page by page as they are read.
    static std::shared_ptr<const MappedFile> map(const std::string& path);

    static constexpr std::size_t kPopulateBytes = std::size_t{64} << 20;

    MappedFile(void* address, std::size_t size);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view bytes() const { return {static_cast<const char*>(address_), size_}; }
    // Whether a page of it was lost to a truncation and read as zeros.
    bool truncated() const;

    // Gives back the memory of the pages wholly inside [from, to) (byte offsets): a large program is
    // read once front to back, and its pages need not stay in the process. Reading them again
    // fetches them from the file.
    void release(std::size_t from, std::size_t to) const;

private:
    void* address_;
    std::size_t size_;
    int slot_ = -1; // in the SIGBUS handler's table
};

} // namespace m350::gcode
