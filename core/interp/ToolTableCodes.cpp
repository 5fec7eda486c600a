// LinuxCNC's G10 L1 / L10 / L11 on a FANUC machine: they write tool P's row of the tool table
// (tool.tbl), as LinuxCNC does:
//   L1  the words are the offsets:                      offset = value
//   L10 the current position shall read `value` in the active work system (G54-G59 with G52/G92):
//                                                       offset = machine - work offsets - value
//   L11 the same in LinuxCNC's fixture 9 (G59.3); this machine has none, so it counts from machine
//       zero:                                           offset = machine - value
// R sets the radius (the row's D is 2R), I and J the lathe angles, Q the orientation. G91 changes
// nothing (the values are absolute in LinuxCNC). The tool must be in the table. The length that
// G43/G44 applies is not re-read: the next G43 or H word does (see latchLengthOffset).
// A FANUC's offset memory keeps numbers in the input unit of the moment, and so does the table
// here: under G20 a computed offset is stored in inches.
#include "core/interp/ModalInterpreter.h"

#include "core/common/Numeric.h"

namespace m350::interp {

using macro::WordValue;

void ModalInterpreter::setToolTable(const Words& words, const WordValue& g10, int kind) {
    const WordValue& p = *words.find('P');
    const int tool = roundToInt(p.value);
    if (std::abs(p.value - tool) > 1e-9 || tool < 1) {
        invalid(p, "G10 L" + std::to_string(kind) + ": P is the tool number (1 and up)");
    }
    std::optional<tools::ToolEntry> row = tools_.find(tool);
    if (!row) {
        invalid(p, "tool " + std::to_string(tool) + " is not in the tool table (tool.tbl): add its row first");
    }
    for (char letter : {'C', 'U', 'V', 'W'}) {
        if (words.has(letter)) {
            invalid(words[letter], "this machine has no " + std::string(1, letter) +
                                       " axis: the table keeps that column, G10 cannot set it");
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
            invalid(*q, "the orientation Q runs from 0 to 9");
        }
        entry.orientation = orientation;
        any = true;
    }
    if (!any) {
        invalid(g10, "G10 L" + std::to_string(kind) + " without offsets has no effect (give X Y Z A B, R, I, J or Q)");
    }
    if (auto why = tools_.put(entry)) {
        invalid(g10, *why);
    }
}

} // namespace m350::interp
