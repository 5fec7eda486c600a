#pragma once

#include "core/gcode/BlockList.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/MappedFile.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode {

// Whether a parsed block can be dropped and parsed again from its line: nothing else refers to it
// (no control statement, no expression, assignment or statement items in the program's pools).
bool isPlainBlock(const Block& block);

// The mapped program file that dropped chunks are parsed again from. The parser records where
// each chunk's first line starts as it reads the file; a chunk is dropped only when it starts
// outside a `/* */` comment and every block of it is plain, so parsing its lines again with a
// fresh BlockParser gives the same blocks.
class ChunkSource : public ChunkReloader {
public:
    struct Start {
        std::size_t offset = 0;     // of the chunk's first line in the text
        std::size_t end = 0;        // of its last block's line (the line end excluded)
        std::uint32_t line = 0;     // its line number
        std::uint32_t lastLine = 0; // the line of the chunk's last block
    };

    // `owner` keeps `text` alive; `mapping`, when the text lies in a mapped file, lets pages go.
    ChunkSource(const Dialect& dialect, std::string fileName, std::uint32_t fileIndex, std::string_view text,
                std::shared_ptr<const void> owner, std::shared_ptr<const MappedFile> mapping);

    void addChunk(Start start) { starts_.push_back(start); }
    // Lets go of the memory of the file's pages in [from, to) of the text, read and not needed now.
    void release(std::size_t from, std::size_t to) const;

    bool reload(std::uint32_t chunk, std::span<Block> out, BlockStorage& storage) const override;

private:
    Dialect dialect_;
    std::string fileName_;
    std::uint32_t fileIndex_;
    std::string_view text_;
    std::shared_ptr<const void> owner_;
    std::shared_ptr<const MappedFile> mapping_;
    std::vector<Start> starts_; // by chunk number
};

} // namespace m350::gcode
