#pragma once

#include "core/gcode/Block.h"

#include <memory>
#include <span>
#include <vector>

namespace m350::gcode {

// Storage for the words of every block of a program, in chunks that never move, so each Block
// can refer to its words with a span and parsing a block allocates nothing of its own.
class WordArena {
public:
    WordArena() = default;
    WordArena(const WordArena&) = delete;
    WordArena& operator=(const WordArena&) = delete;
    WordArena(WordArena&&) = default;
    WordArena& operator=(WordArena&&) = default;

    // Room for `count` consecutive words; valid for the arena's lifetime.
    std::span<Word> allocate(std::size_t count);

private:
    static constexpr std::size_t kChunkWords = 16384;
    std::vector<std::unique_ptr<Word[]>> chunks_;
    std::vector<std::unique_ptr<Word[]>> large_;
    std::size_t used_ = kChunkWords; // of the last chunk
};

} // namespace m350::gcode
