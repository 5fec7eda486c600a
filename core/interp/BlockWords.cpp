#include "core/interp/BlockWords.h"

#include "core/common/Numeric.h"
#include "core/macro/MacroError.h"

namespace m350::interp {

std::string wordText(const macro::WordValue& w) {
    const double whole = std::round(w.value);
    if (std::abs(w.value - whole) < 1e-9) {
        return std::string(1, w.letter) + std::to_string(saturatingInt(whole));
    }
    std::string text = std::to_string(w.value);
    text.erase(text.find_last_not_of('0') + 1);
    return std::string(1, w.letter) + text;
}

[[noreturn]] void invalidWord(const macro::WordValue& w, const Message& words) {
    throw macro::MacroError::of(AlarmCode::InvalidWord, words, w.column);
}

} // namespace m350::interp
