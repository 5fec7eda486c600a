#pragma once

#include "core/common/IndexIterator.h"
#include "core/files/SystemLog.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace m350::ui {

// The newest entries of the System Log as a snapshot carries them: an immutable list, oldest
// first, kept in shared blocks so that the list after one more entry shares all but its newest
// block with the list before (an entry copies at most one block, not the whole list).
class LogTail {
public:
    static constexpr std::size_t kBlock = 64;

    using Iterator = IndexIterator<LogTail, files::LogEntry>;

    LogTail() = default;
    // The newest `most` of `entries`.
    LogTail(const std::vector<files::LogEntry>& entries, std::size_t most);

    // This list with `entry` after its newest, the oldest dropped beyond `most` entries.
    LogTail with(files::LogEntry entry, std::size_t most) const;

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const files::LogEntry& operator[](std::size_t index) const; // 0 is the oldest
    const files::LogEntry& front() const { return (*this)[0]; }
    const files::LogEntry& back() const { return (*this)[size_ - 1]; }
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, size_}; }
    // How many entries were ever added before this list's newest and after it: two lists of one
    // session differ by (b.added() - a.added()) entries at the new end.
    std::uint64_t added() const { return added_; }

private:
    using Block = std::shared_ptr<const std::vector<files::LogEntry>>;
    std::vector<Block> blocks_;
    std::size_t skipped_ = 0; // entries of the first block older than the list
    std::size_t size_ = 0;
    std::uint64_t added_ = 0;
};

} // namespace m350::ui
