#include "core/gcode/LabelIndex.h"

#include <algorithm>
#include <limits>

namespace m350::gcode {

void LabelIndex::build(std::vector<std::pair<std::int32_t, std::uint32_t>> entries) {
    // already in block order: a stable sort by label keeps each label's blocks in file order. CAM
    // output numbers its lines in order, and a stable sort's buffer would be as large again as a
    // 1 GB program's labels: sort only what is not sorted yet.
    const auto byLabel = [](const Entry& a, const Entry& b) { return a.first < b.first; };
    if (!std::is_sorted(entries.begin(), entries.end(), byLabel)) {
        std::stable_sort(entries.begin(), entries.end(), byLabel);
    }
    entries.shrink_to_fit();
    entries_ = std::move(entries);
}

LabelIndex LabelIndex::shifted(std::uint32_t offset) const {
    LabelIndex moved;
    moved.entries_ = entries_;
    for (Entry& entry : moved.entries_) {
        entry.second += offset;
    }
    return moved;
}

std::pair<std::vector<LabelIndex::Entry>::const_iterator, std::vector<LabelIndex::Entry>::const_iterator>
LabelIndex::range(std::int32_t label) const {
    auto low = std::lower_bound(entries_.begin(), entries_.end(), Entry{label, 0});
    auto high = std::upper_bound(low, entries_.end(), Entry{label, std::numeric_limits<std::uint32_t>::max()});
    return {low, high};
}

std::size_t LabelIndex::size() const {
    std::size_t labels = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        labels += i == 0 || entries_[i].first != entries_[i - 1].first ? 1 : 0;
    }
    return labels;
}

bool LabelIndex::contains(std::int32_t label) const {
    auto [low, high] = range(label);
    return low != high;
}

std::vector<std::uint32_t> LabelIndex::at(std::int32_t label) const {
    auto [low, high] = range(label);
    std::vector<std::uint32_t> blocks;
    for (auto it = low; it != high; ++it) {
        blocks.push_back(it->second);
    }
    return blocks;
}

std::optional<std::uint32_t> LabelIndex::find(std::int32_t label, std::uint32_t from) const {
    auto [low, high] = range(label);
    if (low == high) {
        return std::nullopt;
    }
    auto at = std::lower_bound(low, high, Entry{label, from});
    return at != high ? at->second : low->second;
}

} // namespace m350::gcode
