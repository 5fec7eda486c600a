#include "core/common/EchoText.h"

namespace m350 {

std::string clipEcho(std::string text, std::size_t limit) {
    if (text.size() <= limit) {
        return text;
    }
    std::size_t cut = limit;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) {
        --cut; // a continuation byte: the character began before the cut
    }
    const std::size_t dropped = text.size() - cut;
    text.resize(cut);
    return text + "… (" + std::to_string(dropped) + " more bytes)";
}

} // namespace m350
