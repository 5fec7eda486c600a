#include "core/interp/DrillingData.h"

#include "core/macro/MacroError.h"
#include "core/machine/MachineTypes.h"

#include <cmath>
#include <string>

namespace m350::interp {

using macro::MacroError;
using macro::WordValue;

namespace {

// A Q so small that one hole takes more pecks than this is a slip of the pen, not a program to
// simulate for minutes (the steps are produced one at a time, so it is not a memory limit).
constexpr double kMaxPecksPerHole = 10000;
constexpr int kMaxRepeats = 9999; // FANUC K0-K9999

} // namespace

void DrillingData::remember(const BlockWords& words, char drillLetter) {
    if (const WordValue* w = words.find(drillLetter)) {
        bottom_ = w->value;
    }
    if (const WordValue* w = words.find('R')) {
        r_ = w->value;
    }
    if (const WordValue* w = words.find('Q')) {
        q_ = w->value;
    }
    if (const WordValue* w = words.find('P')) {
        if (w->value < 0) {
            invalidWord(*w, message("word_negative_cycle_dwell", {wordText(*w)}));
        }
        p_ = w->value;
    }
}

int DrillingData::repeats(const BlockWords& words) {
    const WordValue* k = words.find('K');
    const WordValue* l = words.find('L');
    if (k && l) {
        invalidWord(*l, message("word_cycle_k_and_l", {wordText(*l)}));
    }
    const WordValue* count = k ? k : l;
    if (!count) {
        return 1;
    }
    if (count->value < 0 || count->value > kMaxRepeats || count->value != std::floor(count->value)) {
        invalidWord(*count, message("word_repeat_count", {wordText(*count), std::to_string(kMaxRepeats)}));
    }
    return static_cast<int>(count->value);
}

void DrillingData::checkComplete(const BlockWords& words, int code, char drillLetter, std::uint32_t column) const {
    const std::string name = "G" + std::to_string(code);
    if (!bottom_) {
        throw MacroError::of(AlarmCode::MissingAddress,
                             message("cycle_needs_bottom", {name, std::string(1, drillLetter)}), column);
    }
    if (!r_) {
        throw MacroError::of(AlarmCode::MissingAddress, message("cycle_needs_r", {name}), column);
    }
    if ((code == 73 || code == 83) && q_ <= 0) {
        const WordValue* q = words.find('Q');
        throw MacroError::of(q ? AlarmCode::InvalidWord : AlarmCode::MissingAddress, message("cycle_needs_q", {name}),
                             q ? q->column : column);
    }
}

DrillingCycle DrillingData::resolve(const BlockWords& words, int code, int drillAxis, const Frame& frame,
                                    std::uint32_t column) const {
    const std::string name = "G" + std::to_string(code);
    DrillingCycle cycle;
    cycle.code = code;
    cycle.drillAxis = drillAxis;
    cycle.initialLevel = *initialLevel_;
    if (frame.incremental) { // FANUC and rs274: R from the initial level, the bottom from R
        cycle.r = cycle.initialLevel + *r_ * frame.unit;
        cycle.bottom = cycle.r + *bottom_ * frame.unit;
    } else {
        cycle.r = *r_ * frame.unit + frame.offset;
        cycle.bottom = *bottom_ * frame.unit + frame.offset;
    }
    if (cycle.bottom > cycle.r + 1e-9) {
        const WordValue* r = words.find('R');
        const std::string letter(1, machine::kAxisNames[static_cast<std::size_t>(drillAxis)]);
        throw MacroError::of(AlarmCode::InvalidWord, message("cycle_bottom_above_r", {name, letter}),
                             r ? r->column : column);
    }
    cycle.returnToR = frame.returnToR;
    cycle.peck = q_ * frame.unit;
    if ((code == 73 || code == 83) && (cycle.r - cycle.bottom) / cycle.peck > kMaxPecksPerHole) {
        const WordValue* q = words.find('Q');
        throw MacroError::of(AlarmCode::InvalidWord,
                             message("cycle_too_many_pecks", {name, std::to_string(static_cast<int>(kMaxPecksPerHole))}),
                             q ? q->column : column);
    }
    cycle.peckClearance = frame.peckClearance;
    cycle.dwell = p_ * frame.dwellScale;
    return cycle;
}

} // namespace m350::interp
