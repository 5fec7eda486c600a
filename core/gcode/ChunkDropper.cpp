#include "core/gcode/ChunkDropper.h"

#include <utility>

namespace m350::gcode {

ChunkDropper::ChunkDropper(Program& program, std::shared_ptr<ChunkSource> source)
    : program_(program), source_(std::move(source)) {}

ChunkDropper::Marks ChunkDropper::marks() const {
    return {program_.words.mark(),          program_.assignments.mark(),
            program_.text.mark(),           program_.statementItems.mark(),
            program_.statements.size(),     program_.expressions.size()};
}

void ChunkDropper::beforeLine(std::size_t offset, std::size_t end, std::uint32_t line, bool commentOpen) {
    lineOffset_ = offset;
    lineEnd_ = end;
    // The next block starts a chunk: what the arenas hold now is what stays if it is dropped.
    lineStartsChunk_ = program_.blocks.size() % BlockList::kChunkSize == 0;
    if (lineStartsChunk_) {
        atChunkStart_ = marks();
        start_ = {offset, end, line, line};
        droppable_ = !commentOpen; // parsed again alone, a line inside a comment would read as code
    }
}

void ChunkDropper::afterLine(const Block* added, bool diagnosed) {
    if (added == nullptr) {
        if (!lineStartsChunk_) {
            droppable_ = droppable_ && !diagnosed;
        }
        return;
    }
    droppable_ = droppable_ && !diagnosed && isPlainBlock(*added);
    start_.lastLine = added->location.line;
    start_.end = lineEnd_;
    if (program_.blocks.size() % BlockList::kChunkSize != 0) {
        return;
    }
    const auto chunk = static_cast<std::uint32_t>(program_.blocks.size() / BlockList::kChunkSize - 1);
    source_->addChunk(start_);
    const Marks now = marks();
    if (droppable_ && now.expressions == atChunkStart_.expressions && now.statements == atChunkStart_.statements &&
        program_.blocks.drop(chunk, source_)) {
        program_.words.rewind(atChunkStart_.words);
        program_.assignments.rewind(atChunkStart_.assignments);
        program_.text.rewind(atChunkStart_.text);
        program_.statementItems.rewind(atChunkStart_.statementItems);
    }
    source_->release(released_, lineOffset_);
    released_ = lineOffset_;
}

void ChunkDropper::finish(std::size_t textSize) {
    source_->release(released_, textSize);
    released_ = textSize;
}

} // namespace m350::gcode
