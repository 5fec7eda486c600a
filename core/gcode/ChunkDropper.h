#pragma once

#include "core/gcode/ChunkSource.h"
#include "core/gcode/Program.h"

#include <cstddef>
#include <cstdint>
#include <memory>

namespace m350::gcode {

// The parser's first pass over a program kept in part (see Parser::addSource): as the blocks of
// the main file are added, it decides for each chunk whether it may be dropped, and drops it with
// everything its blocks refer to, so only the chunks that jumps, loops and expressions need stay.
class ChunkDropper {
public:
    ChunkDropper(Program& program, std::shared_ptr<ChunkSource> source);

    // Before each line is parsed: where it starts and ends, whether a `/* */` comment is open
    // before it.
    void beforeLine(std::size_t offset, std::size_t end, std::uint32_t line, bool commentOpen);
    // After the line: the block it gave, just added to the program (or none), and whether the line
    // gave diagnostics (a chunk with any stays, so that nothing said once is lost).
    void afterLine(const Block* added, bool diagnosed);
    // After the last line: the file's pages are let go.
    void finish(std::size_t textSize);

private:
    struct Marks {
        Arena<Word>::Mark words;
        Arena<Assignment>::Mark assignments;
        Arena<char>::Mark text;
        Arena<StatementItem>::Mark statementItems;
        std::size_t statements = 0;
        std::size_t expressions = 0;
    };
    Marks marks() const;

    Program& program_;
    std::shared_ptr<ChunkSource> source_;
    Marks atChunkStart_;
    ChunkSource::Start start_;
    bool droppable_ = true;
    bool lineStartsChunk_ = false;
    std::size_t lineOffset_ = 0;
    std::size_t lineEnd_ = 0;
    std::size_t released_ = 0; // the file's pages before this were let go
};

} // namespace m350::gcode
