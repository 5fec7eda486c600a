#include "core/tools/ToolTable.h"

#include <algorithm>
#include <cmath>

namespace m350::tools {

namespace {

constexpr std::array<std::string_view, kToolTypeCount> kTypeKeys{
    "flat", "ball", "bull", "drill", "tap", "chamfer", "engrave", "face", "reamer", "probe", "other"};

bool finite(const std::optional<double>& v) { return !v || std::isfinite(*v); }

} // namespace

std::string_view toolTypeKey(ToolType type) { return kTypeKeys[static_cast<std::size_t>(type)]; }

std::optional<ToolType> toolTypeFromKey(std::string_view key) {
    auto found = std::find(kTypeKeys.begin(), kTypeKeys.end(), key);
    if (found == kTypeKeys.end()) {
        return std::nullopt;
    }
    return static_cast<ToolType>(found - kTypeKeys.begin());
}

std::optional<Message> invalidEntry(const ToolEntry& entry) {
    const std::string tool = std::to_string(entry.tool);
    if (entry.tool < 1) {
        return message("tool_table_tool_zero");
    }
    if (entry.pocket < 0 || entry.pocket > ToolTable::kMaxPocket) {
        return message("tool_table_pocket_range", {tool, std::to_string(entry.pocket)});
    }
    for (std::size_t axis = 0; axis < entry.offsets.size(); ++axis) {
        if (!finite(entry.offsets[axis])) {
            return message("tool_table_offset_not_finite", {tool, std::string(1, kOffsetLetters[axis])});
        }
    }
    if (!finite(entry.diameter) || !finite(entry.frontAngle) || !finite(entry.backAngle) || !finite(entry.lengthWear) ||
        !finite(entry.radiusWear)) {
        return message("tool_table_not_finite", {tool});
    }
    if (entry.orientation && (*entry.orientation < 0 || *entry.orientation > 9)) {
        return message("tool_table_orientation", {tool});
    }
    if (entry.maxRpm && !(std::isfinite(*entry.maxRpm) && *entry.maxRpm > 0.0)) {
        return message("tool_table_rpm", {tool});
    }
    if (entry.teeth && *entry.teeth < 1) {
        return message("tool_table_teeth", {tool});
    }
    if (entry.comment.find_first_of("\r\n") != std::string::npos) {
        return message("tool_table_comment_line", {tool});
    }
    return std::nullopt;
}

std::vector<ToolEntry> ToolTable::entries() const {
    std::vector<ToolEntry> out;
    out.reserve(count_);
    for (const Line& line : lines_) {
        if (line.entry) {
            out.push_back(*line.entry);
        }
    }
    return out;
}

const ToolEntry* ToolTable::find(int tool) const {
    for (const Line& line : lines_) {
        if (line.entry && line.entry->tool == tool) {
            return &*line.entry;
        }
    }
    return nullptr;
}

const ToolEntry* ToolTable::findPocket(int pocket) const {
    for (const Line& line : lines_) {
        if (line.entry && line.entry->pocket == pocket) {
            return &*line.entry;
        }
    }
    return nullptr;
}

std::optional<Message> ToolTable::put(const ToolEntry& entry) {
    if (auto why = invalidEntry(entry)) {
        return why;
    }
    if (const ToolEntry* other = findPocket(entry.pocket); other && other->tool != entry.tool) {
        return message("tool_table_pocket_taken", {std::to_string(entry.pocket), std::to_string(other->tool)});
    }
    for (Line& line : lines_) {
        if (line.entry && line.entry->tool == entry.tool) {
            if (*line.entry != entry) {
                line.entry = entry;
                line.text.clear();
            }
            return std::nullopt;
        }
    }
    if (count_ >= static_cast<std::size_t>(kMaxTools)) {
        return message("tool_table_full", {std::to_string(kMaxTools)});
    }
    lines_.push_back({entry, {}});
    ++count_;
    return std::nullopt;
}

bool ToolTable::remove(int tool) {
    auto found = std::find_if(lines_.begin(), lines_.end(),
                              [tool](const Line& line) { return line.entry && line.entry->tool == tool; });
    if (found == lines_.end()) {
        return false;
    }
    lines_.erase(found);
    --count_;
    return true;
}

std::optional<int> ToolTable::freePocket(int preferred) const {
    if (preferred >= 1 && preferred <= kMaxPocket && !findPocket(preferred)) {
        return preferred;
    }
    std::vector<bool> taken(static_cast<std::size_t>(kMaxPocket) + 1, false);
    for (const Line& line : lines_) {
        if (line.entry) {
            taken[static_cast<std::size_t>(line.entry->pocket)] = true;
        }
    }
    for (int pocket = 1; pocket <= kMaxPocket; ++pocket) {
        if (!taken[static_cast<std::size_t>(pocket)]) {
            return pocket;
        }
    }
    return std::nullopt;
}

void ToolTable::appendRow(ToolEntry entry, std::string text) {
    lines_.push_back({std::move(entry), std::move(text)});
    ++count_;
}

void ToolTable::appendText(std::string text) { lines_.push_back({std::nullopt, std::move(text)}); }

} // namespace m350::tools
