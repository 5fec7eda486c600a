#pragma once

#include "core/common/Message.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace m350::tools {

// What kind of cutter a tool is: one of the extras LinuxCNC's table lacks. Stored by key
// ("flat", "ball" ...) in the comment's {...} group (see ToolEntry).
enum class ToolType { Flat, Ball, Bull, Drill, Tap, Chamfer, Engrave, Face, Reamer, Probe, Other };
inline constexpr std::size_t kToolTypeCount = 11;
std::string_view toolTypeKey(ToolType type);
std::optional<ToolType> toolTypeFromKey(std::string_view key);

// The offset columns of a LinuxCNC tool table, in its order.
inline constexpr std::array<char, 9> kOffsetLetters{'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};
inline constexpr int kZ = 2;

// One row of tool.tbl: `T1 P1 Z66.323 D6 ;6 mm end mill {rpm=24000 teeth=2 type=flat}`.
// Every optional says whether the row writes that word, so a row is written back with the words it
// had. Lengths are in machine units (mm), angles in degrees.
//
// The extras (maximum rpm, number of teeth, type) live in a `{key=value ...}` group at the end of
// the comment: LinuxCNC skips a whole row with any word it does not know (`S24000` loses the tool),
// but keeps a comment as it is, so the file stays LinuxCNC's.
struct ToolEntry {
    int tool = 0;   // T: 1 and up, unique
    int pocket = 0; // P: 0 (the spindle, for random changers) to 1000, unique
    std::array<std::optional<double>, 9> offsets{}; // X Y Z A B C U V W
    std::optional<double> diameter;   // D
    std::optional<double> frontAngle; // I (lathe)
    std::optional<double> backAngle;  // J (lathe)
    std::optional<int> orientation;   // Q 0-9 (lathe)
    std::optional<double> maxRpm;     // {rpm=...}
    std::optional<int> teeth;         // {teeth=...}
    std::optional<ToolType> type;     // {type=...}
    // FANUC offset memory C's wear columns, where LinuxCNC's table has none: H wear (length) and D
    // wear (radius), {hwear=... dwear=...}. The geometry columns are the row's Z and D / 2.
    std::optional<double> lengthWear; // {hwear=...}
    std::optional<double> radiusWear; // {dwear=...}
    std::string comment;              // after ';', without the extras group

    double offset(int axis) const { return offsets[static_cast<std::size_t>(axis)].value_or(0.0); }
    bool hasExtras() const { return maxRpm || teeth || type || lengthWear || radiusWear; }
    bool operator==(const ToolEntry&) const = default;
};

// The whole file, in its order: tool rows and the lines that are no rows (comments, blank lines,
// and rows the reader refused, kept as written so that saving loses nothing of the user's). A row
// keeps its original text until it is changed, so an untouched file is written back byte for byte.
class ToolTable {
public:
    static constexpr int kMaxTools = 1000; // LinuxCNC's limit of 1000 pockets
    static constexpr int kMaxPocket = 1000;

    struct Line {
        std::optional<ToolEntry> entry; // a tool row; nullopt: `text` only
        std::string text;               // as read; empty once the row is changed
        bool operator==(const Line&) const = default;
    };

    const std::vector<Line>& lines() const { return lines_; }
    std::vector<ToolEntry> entries() const;
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    const ToolEntry* find(int tool) const;
    const ToolEntry* findPocket(int pocket) const;

    // Adds a row, or replaces the row of the same tool where it stands. Refuses (the reason) a value
    // a tool table cannot hold, a pocket another tool has, or a 1001st tool; changes nothing then.
    std::optional<Message> put(const ToolEntry& entry);
    bool remove(int tool);
    // The lowest pocket no tool holds, `preferred` when free; nullopt when all 1000 are taken.
    std::optional<int> freePocket(int preferred) const;

    // The reader's way in: a row as read (already checked), or a line that is no row.
    void appendRow(ToolEntry entry, std::string text);
    void appendText(std::string text);

    std::string_view lineEnd() const { return lineEnd_; }
    void setLineEnd(std::string_view end) { lineEnd_ = std::string(end); }
    bool finalLineEnd() const { return finalLineEnd_; }
    void setFinalLineEnd(bool on) { finalLineEnd_ = on; }

    bool operator==(const ToolTable&) const = default;

private:
    std::vector<Line> lines_;
    std::size_t count_ = 0;
    std::string lineEnd_ = "\n";
    bool finalLineEnd_ = true;
};

// Why `entry` cannot be a row of any tool table (tool below 1, pocket beyond 0-1000, Q beyond 0-9,
// a number that is not finite, teeth below 1, rpm not positive), or nullopt.
std::optional<Message> invalidEntry(const ToolEntry& entry);

} // namespace m350::tools
