// FANUC's look-ahead and contour-control modes: `G05.1 Q1` (AI contour control), `G08 P1`
// (look-ahead control), `G05 P10000` (high-precision contour control) and their `Q0` / `P0`. They
// change how the control plans feed around corners, never the programmed path, which is all the
// simulator moves along; so they are accepted, checked and recorded for the trace.
#include "core/interp/ModalInterpreter.h"

#include "core/common/Numeric.h"

#include <cmath>

namespace m350::interp {

using macro::WordValue;

namespace {

bool isCode(double value, double code) {
    return std::abs(value - code) < 1e-6;
}

// A switch word of the mode: which letter and which values it takes.
struct ModeCode {
    double code;
    const char* name; // as written in messages and the trace
    char letter;
    int on;
    const char* what;
    const char* chinese; // `what` in the panel's zh_CN
};

constexpr ModeCode kModes[] = {
    {5.1, "G05.1", 'Q', 1, "AI contour control", "AI轮廓控制"},
    {8, "G08", 'P', 1, "look-ahead control", "先行控制"},
    {5, "G05", 'P', 10000, "high-precision contour control", "高精度轮廓控制"},
};

const ModeCode* modeOf(double value) {
    for (const ModeCode& mode : kModes) {
        if (isCode(value, mode.code)) {
            return &mode;
        }
    }
    return nullptr;
}

} // namespace

bool ModalInterpreter::isLookAheadCode(double value) { return modeOf(value) != nullptr; }

bool ModalInterpreter::isLookAheadBlock(const Words& words) {
    for (const WordValue& g : words.g) {
        if (modeOf(g.value)) {
            return true;
        }
    }
    return false;
}

// Records the mode `g` switches; false when `g` is no look-ahead code. FANUC wants these codes in a
// block of their own (G05.1 may carry R, the accuracy level), so any other word is refused rather
// than taken as a canned cycle's P or Q.
bool ModalInterpreter::lookAheadCode(const WordValue& g, const Words& words) {
    const ModeCode* mode = modeOf(g.value);
    if (!mode) {
        return false;
    }
    const std::string on = std::string(1, mode->letter) + std::to_string(mode->on);
    const WordValue* value = words.find(mode->letter);
    if (!value || (value->value != 0 && value->value != mode->on)) {
        invalidWord(value ? *value : g, message("word_look_ahead_usage", {wordText(value ? *value : g), mode->name, on,
                                                                      bilingual(mode->what, mode->chinese),
                                                                      std::string(1, mode->letter)}));
    }
    const std::uint32_t allowed = Words::bit(mode->letter) | Words::bit('N') | (isCode(mode->code, 5.1) ? Words::bit('R') : 0);
    if ((words.present & ~allowed) != 0 || words.g.size() > 1 || !words.m.empty()) {
        invalidWord(g, message("word_look_ahead_alone", {wordText(g), mode->name, on, bilingual(mode->what, mode->chinese),
                                                     std::string(1, mode->letter)}));
    }
    std::string text = std::string(mode->name) + " " + mode->letter + std::to_string(roundToInt(value->value));
    if (const WordValue* r = words.find('R'); r && isCode(mode->code, 5.1)) {
        text += " R" + std::to_string(roundToInt(r->value));
    }
    lookAheadChanges_.push_back(std::move(text));
    return true;
}

std::vector<std::string> ModalInterpreter::takeLookAheadChanges() {
    std::vector<std::string> out;
    out.swap(lookAheadChanges_);
    return out;
}

} // namespace m350::interp
