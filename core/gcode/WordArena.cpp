#include "core/gcode/WordArena.h"

namespace m350::gcode {

std::span<Word> WordArena::allocate(std::size_t count) {
    if (count == 0) {
        return {};
    }
    if (count > kChunkWords) {
        // A block with more words than a chunk holds gets storage of its own.
        large_.push_back(std::make_unique<Word[]>(count));
        return {large_.back().get(), count};
    }
    if (used_ + count > kChunkWords) {
        chunks_.push_back(std::make_unique<Word[]>(kChunkWords));
        used_ = 0;
    }
    std::span<Word> room(chunks_.back().get() + used_, count);
    used_ += count;
    return room;
}

} // namespace m350::gcode
