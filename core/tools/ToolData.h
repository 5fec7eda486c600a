#pragma once

#include "core/params/ParameterTable.h"
#include "core/gcode/Dialect.h"
#include "core/tools/ToolTable.h"

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <vector>
#include <string>
#include <string_view>
#include <utility>

namespace m350::tools {

// The M350 keeps each tool's Z offset (the machine Z where it touched the setter) in a parameter:
// T1..T16 in 930-945 (#1430-#1445), the virtual tools above the magazine's capacity (param 801) in
// 973-992. The parameter of `tool`, or nullopt when the M350 has none for it.
std::optional<int> m350ZParameter(int tool, const params::ParameterTable& parameters);

// An offset computed from a position (touch off, G10 L10/L11), kept to 1e-6 of its unit as
// LinuxCNC writes tool.tbl (%f), so that 0 - (-12.5) - 2 is 10.5 and not 10.499999999999998.
double roundedOffset(double value);

// A machine's tool data: its one tool table (tool.tbl), with one store for every value.
//
// On the M350 the Z of a tool that has a Z-offset parameter lives in that parameter and nowhere
// else: table() reads it from there and put()/setZ() write it there, so a macro writing #1430
// (O502 setting a tool), the Param page writing 930 and an edit of the table are the same change.
// A tool with such a parameter that is not in the table yet appears in table() once its parameter
// is not 0. The table's other columns (pocket, D, comment, extras ...) live in the rows.
//
// On a FANUC the table also is the offset memory: offset number n is tool n's row, as LinuxCNC's
// G43 Hn and G41 Dn read tool n. The machine folder says which memory the control has:
//   A  one value per number (#2001-#2400, G10 L11 P R, or L1): the row's Z; D n reads the row's
//      diameter / 2 when the row has a D word (LinuxCNC's radius), else that same value;
//   C  four per number (1-200): H geometry = the row's Z, H wear {hwear=}, D geometry = the row's
//      D / 2, D wear {dwear=}; G10 L10 / L11 / L12 / L13 write them, #2001-#2200 are the H wear and
//      #2201-#2400 the H geometry (FANUC's numbering for up to 200 offsets); H n applies geometry +
//      wear, and so does D n.
// Writing an offset makes the row when there is none.
enum class OffsetMemory { A, C };
enum class OffsetRegister { LengthGeometry, LengthWear, RadiusGeometry, RadiusWear };
std::string_view offsetRegisterName(OffsetRegister r); // "H geometry" ...

class ToolData {
public:
    static constexpr int kOffsetNumbers = 400; // FANUC Memory A: offsets 1-400
    static constexpr int kMemoryCOffsets = 200; // Memory C as #2001-#2400 reach it: 1-200

    // `loaded`: the folder's tool.tbl, whose Z values then replace the M350's parameters; without
    // one, an M350 starts from its parameters (rows T1..T16, pocket = tool).
    ToolData(const gcode::Dialect& dialect, params::ParameterTable& parameters, std::optional<ToolTable> loaded);

    ToolTable table() const;
    std::optional<ToolEntry> find(int tool) const;
    // Adds or replaces a row (see ToolTable::put); the reason when refused, nothing changed then.
    std::optional<Message> put(const ToolEntry& entry);
    bool remove(int tool);
    // The whole table at once (an import, or putting back a saved state): M350 tools it lacks get Z 0.
    void replace(const ToolTable& table);
    // A tool's Z (0 when it has none); setZ makes the row (pocket = tool when free) when missing.
    double z(int tool) const;
    std::optional<Message> setZ(int tool, double z);
    // A tool's diameter (the row's D), when its row has one.
    std::optional<double> diameter(int tool) const;

    // FANUC offset memory over the table.
    void setOffsetMemory(OffsetMemory memory) { memory_ = memory; }
    OffsetMemory offsetMemory() const { return memory_; }
    int offsetCount() const { return memory_ == OffsetMemory::A ? kOffsetNumbers : kMemoryCOffsets; }
    bool validOffsetNumber(int number) const { return number >= 1 && number <= offsetCount(); }
    // What H n and D n apply (memory C: geometry + wear).
    double lengthOffset(int number) const;
    double radiusOffset(int number) const;
    // One register of offset n (memory A: LengthGeometry is its one value).
    double registerValue(OffsetRegister r, int number) const;
    std::optional<Message> setRegister(OffsetRegister r, int number, double value);
    // #2001-#2400 (index 1-400): memory A offset n; memory C H wear 1-200, then H geometry 1-200.
    double offsetVariable(int index) const;
    std::optional<Message> setOffsetVariable(int index, double value);

    // LinuxCNC's tool table codes work on a machine that keeps a tool.tbl (FANUC dialect): G10 L0
    // reads the file again. What the run itself changed stays as it is (LinuxCNC writes each G10 L1
    // / L10 / L11 and M61 to the file at once, so its reload finds them there). The reason when the
    // file cannot be read; its skipped lines in `skipped`.
    void setSourceFile(std::string path) { sourceFile_ = std::move(path); }
    bool keepsToolTable() const { return !sourceFile_.empty(); }
    std::optional<Message> reload(std::vector<std::string>& skipped); // skipped: each issue bilingual()
    // LinuxCNC's random tool changer ([EMCIO]RANDOM_TOOLCHANGER = 1) at M6: tool `to` leaves its
    // pocket for the spindle (pocket 0) and tool `from` goes into that pocket. Tools not in the
    // table keep no pocket.
    void swapPockets(int from, int to);

    // Whether anything changed between two marks (edits here, and the M350's Z parameters however
    // they were written).
    struct Mark {
        std::uint64_t revision = 0;
        std::array<double, 36> zParameters{};
        bool operator==(const Mark&) const = default;
    };
    Mark mark() const;

private:
    bool m350() const { return dialect_->id == gcode::DialectId::M350; }
    std::optional<int> zParameter(int tool) const;
    std::vector<int> toolsWithZParameters() const;

    std::pair<OffsetRegister, int> variableRegister(int index) const;
    bool setPocket(int tool, int pocket);

    const gcode::Dialect* dialect_;
    params::ParameterTable* parameters_;
    OffsetMemory memory_ = OffsetMemory::A;
    std::string sourceFile_;
    std::set<int> changedSinceLoad_; // tools whose rows this session wrote (G10 L0 keeps them)
    ToolTable rows_; // M350: the Z of a tool with a Z parameter is not read from here
    std::uint64_t revision_ = 0;
};

} // namespace m350::tools
