#include "ui/session/LogTail.h"

#include <algorithm>

namespace m350::ui {

LogTail::LogTail(const std::vector<files::LogEntry>& entries, std::size_t most) {
    const std::size_t first = entries.size() > most ? entries.size() - most : 0;
    for (std::size_t at = first; at < entries.size(); at += kBlock) {
        const auto from = entries.begin() + static_cast<std::ptrdiff_t>(at);
        const auto to = entries.begin() + static_cast<std::ptrdiff_t>(std::min(at + kBlock, entries.size()));
        blocks_.push_back(std::make_shared<const std::vector<files::LogEntry>>(from, to));
    }
    size_ = entries.size() - first;
    added_ = entries.size();
}

LogTail LogTail::with(files::LogEntry entry, std::size_t most) const {
    LogTail next = *this;
    if (next.blocks_.empty() || next.blocks_.back()->size() == kBlock) {
        next.blocks_.push_back(std::make_shared<const std::vector<files::LogEntry>>(1, std::move(entry)));
    } else {
        auto newest = std::make_shared<std::vector<files::LogEntry>>();
        newest->reserve(next.blocks_.back()->size() + 1);
        *newest = *next.blocks_.back();
        newest->push_back(std::move(entry));
        next.blocks_.back() = std::move(newest);
    }
    ++next.size_;
    ++next.added_;
    for (; next.size_ > most; --next.size_) {
        if (++next.skipped_ == next.blocks_.front()->size()) {
            next.blocks_.erase(next.blocks_.begin());
            next.skipped_ = 0;
        }
    }
    return next;
}

const files::LogEntry& LogTail::operator[](std::size_t index) const {
    index += skipped_;
    // every block but the newest is full
    return (*blocks_[index / kBlock])[index % kBlock];
}

} // namespace m350::ui
