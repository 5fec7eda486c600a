// G10 L1 and L10-L13 on a FANUC machine, in the two forms the source documents write:
//   FANUC 0i, `G10 L.. P<offset> R<value>` (R and nothing of LinuxCNC's): the offset memory the
//   machine has (ToolData.h). Memory A: L11 (or L1, the older form) writes offset P. Memory C:
//   L10 H geometry, L11 H wear, L12 D geometry, L13 D wear. G91 adds R to the register.
//   LinuxCNC, `G10 L1 / L10 / L11 P<tool>` with axis words (or I J Q): tool P's row of the table:
//     L1  the words are the offsets:                      offset = value
//     L10 the current position shall read `value` in the active work system (G54-G59 with G52/G92):
//                                                         offset = machine - work offsets - value
//     L11 the same in LinuxCNC's fixture 9 (G59.3); this machine has none, so it counts from machine
//         zero:                                           offset = machine - value
//     R sets the radius (the row's D is 2R), I and J the lathe angles, Q the orientation. G91
//     changes nothing (the values are absolute in LinuxCNC). The tool must be in the table.
// A block is never read both ways: a form that names a register other than the one the programmer
// meant on this machine (L10, L12, L13 on memory A; L1 P R on memory C; L12/L13 with axis words) is
// refused at its L word. The length G43/G44 applies is not re-read: the next G43 or H word does
// (see latchLengthOffset). A FANUC's offset memory keeps numbers in the input unit of the moment,
// and so does the table here: under G20 a computed offset is stored in inches.
#include "core/interp/ModalInterpreter.h"

#include "core/common/Numeric.h"

namespace m350::interp {

using macro::WordValue;

// LinuxCNC's own tool table codes (its seed: G10 L0, M61, the random changer; G43.1 beside them)
// belong to a machine that keeps a LinuxCNC tool.tbl; elsewhere they would be guesses.
void ModalInterpreter::needLinuxCncTable(const WordValue& w, const std::string& what) const {
    if (!tools_.keepsToolTable()) {
        invalidWord(w, message("word_linuxcnc_table", {wordText(w), what}));
    }
}

// G10 L0: read tool.tbl again (LinuxCNC refuses it while a tool is loaded: M61 Q0 first).
void ModalInterpreter::reloadToolTable(const WordValue& g10) {
    needLinuxCncTable(g10, bilingual("G10 L0 (reload the tool table)", "G10 L0（重新读入刀具表）"));
    if (const int loaded = spindleTool_ ? spindleTool_() : 0; loaded != 0) {
        invalidWord(g10, message("word_g10_l0_loaded", {wordText(g10), std::to_string(loaded)}));
    }
    std::vector<std::string> skipped;
    if (auto why = tools_.reload(skipped)) {
        invalidWord(g10, message("word_g10_l0_failed", {wordText(g10), bilingual(*why)}));
    }
    reloadIssues_ = std::move(skipped);
}

// G43.1 Z..: LinuxCNC's dynamic tool length offset, the value itself instead of a table's entry;
// the block moves nothing (its Z is the offset), the next move applies it. G49 cancels it.
void ModalInterpreter::setDynamicLength(const WordValue& g, const Words& words) {
    needLinuxCncTable(g, bilingual("G43.1 (dynamic tool length)", "G43.1（动态刀具长度）"));
    for (char letter : {'X', 'Y', 'A', 'B', 'H'}) {
        if (words.has(letter)) {
            invalidWord(words[letter], message("word_g43_1_z_only", {wordText(words[letter]), std::string(1, letter)}));
        }
    }
    if (!words.has('Z')) {
        invalidWord(g, message("word_g43_1_needs_z", {wordText(g)}));
    }
    state_.groups[8] = 43.1;
    state_.lengthOffset = 0;
    state_.lengthOffsetValue = words['Z'].value;
    dynamicLength_ = true;
}

// M61 Qn: the spindle holds tool n now, without a change (LinuxCNC's "set current tool").
void ModalInterpreter::setToolNumber(const WordValue& m, const Words& words) {
    needLinuxCncTable(m, bilingual("M61 (set the tool number)", "M61（设定刀号）"));
    const WordValue* q = words.find('Q');
    const int tool = q ? roundToInt(q->value) : -1;
    if (!q || std::abs(q->value - tool) > 1e-9 || tool < 0) {
        invalidWord(q ? *q : m, message("word_m61_needs_q", {wordText(q ? *q : m)}));
    }
    state_.selectedTool = tool;
    toolChange_ = ToolChange{tool, true};
}

void ModalInterpreter::setToolOffsets(const Words& words, const WordValue& g10, int kind) {
    const bool linuxCnc = words.hasAxis() || words.has('I') || words.has('J') || words.has('Q') || words.has('C') ||
                          words.has('U') || words.has('V') || words.has('W');
    const WordValue& l = words['L'];
    if (linuxCnc) {
        if (kind == 12 || kind == 13) {
            invalidWord(l, message("word_g10_d_offset_axes", {wordText(l), std::to_string(kind)}));
        }
        setToolTable(words, g10, kind);
        return;
    }
    if (!words.has('R')) {
        invalidWord(g10, message("word_g10_needs_r", {wordText(g10), std::to_string(kind)}));
    }
    setOffsetRegister(words, kind);
}

void ModalInterpreter::setOffsetRegister(const Words& words, int kind) {
    const WordValue& l = words['L'];
    const WordValue& p = words['P'];
    const WordValue& r = words['R'];
    tools::OffsetRegister which = tools::OffsetRegister::LengthGeometry;
    if (tools_.offsetMemory() == tools::OffsetMemory::A) {
        if (kind != 1 && kind != 11) {
            invalidWord(l, message("word_g10_memory_a", {wordText(l)}));
        }
    } else {
        if (kind == 1) {
            invalidWord(l, message("word_g10_memory_c", {wordText(l)}));
        }
        which = kind == 10   ? tools::OffsetRegister::LengthGeometry
                : kind == 11 ? tools::OffsetRegister::LengthWear
                : kind == 12 ? tools::OffsetRegister::RadiusGeometry
                             : tools::OffsetRegister::RadiusWear;
    }
    const int number = roundToInt(p.value);
    if (std::abs(p.value - number) > 1e-9 || !tools_.validOffsetNumber(number)) {
        invalidWord(p, message("word_g10_offset_number", {wordText(p), std::to_string(kind), std::to_string(tools_.offsetCount())}));
    }
    const double value = (state_.incremental() ? tools_.registerValue(which, number) : 0.0) + r.value;
    if (auto why = tools_.setRegister(which, number, value)) {
        invalidWord(l, message("word_refused", {wordText(l), bilingual(*why)}));
    }
}

void ModalInterpreter::setToolTable(const Words& words, const WordValue& g10, int kind) {
    const WordValue& p = *words.find('P');
    const int tool = roundToInt(p.value);
    if (std::abs(p.value - tool) > 1e-9 || tool < 1) {
        invalidWord(p, message("word_g10_tool_number", {wordText(p), std::to_string(kind)}));
    }
    std::optional<tools::ToolEntry> row = tools_.find(tool);
    if (!row) {
        invalidWord(p, message("word_tool_not_in_table", {wordText(p), std::to_string(tool)}));
    }
    for (char letter : {'C', 'U', 'V', 'W'}) {
        if (words.has(letter)) {
            invalidWord(words[letter], message("word_g10_no_axis", {wordText(words[letter]), std::string(1, letter)}));
        }
    }
    tools::ToolEntry entry = *row;
    bool any = false;
    const machine::Axes position = machine_.position();
    machine::Axes workOffsets = workOffset();
    workOffsets(2) -= toolLengthOffset();
    for (int axis = 0; axis < machine::kAxisCount; ++axis) {
        const WordValue* w = words.find(machine::kAxisNames[static_cast<std::size_t>(axis)]);
        if (!w) {
            continue;
        }
        any = true;
        const double unit = axisUnit(axis);
        double value = w->value;
        if (kind != 1) {
            const double from = kind == 10 ? workOffsets(axis) : 0.0;
            value = tools::roundedOffset((position(axis) - from - w->value * unit) / unit);
        }
        entry.offsets[static_cast<std::size_t>(axis)] = value;
    }
    if (const WordValue* r = words.find('R')) {
        entry.diameter = 2.0 * r->value;
        any = true;
    }
    if (const WordValue* i = words.find('I')) {
        entry.frontAngle = i->value;
        any = true;
    }
    if (const WordValue* j = words.find('J')) {
        entry.backAngle = j->value;
        any = true;
    }
    if (const WordValue* q = words.find('Q')) {
        const int orientation = roundToInt(q->value);
        if (std::abs(q->value - orientation) > 1e-9 || orientation < 0 || orientation > 9) {
            invalidWord(*q, message("word_orientation_range", {wordText(*q)}));
        }
        entry.orientation = orientation;
        any = true;
    }
    if (!any) {
        invalidWord(g10, message("word_g10_no_effect", {wordText(g10), std::to_string(kind)}));
    }
    if (auto why = tools_.put(entry)) {
        invalidWord(g10, message("word_refused", {wordText(g10), bilingual(*why)}));
    }
}

} // namespace m350::interp
