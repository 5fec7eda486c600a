#include "core/gcode/ChunkSource.h"

#include "core/gcode/BlockParser.h"
#include "core/gcode/LineSplitter.h"

#include <algorithm>

namespace m350::gcode {

bool isPlainBlock(const Block& block) {
    if (block.control != Control::None || !block.assignments.empty() || block.condition != kNoExpr ||
        block.target != kNoExpr || block.statement != 0) {
        return false;
    }
    return std::all_of(block.words.begin(), block.words.end(), [](const Word& w) { return w.isNumber(); });
}

ChunkSource::ChunkSource(const Dialect& dialect, std::string fileName, std::uint32_t fileIndex,
                         std::string_view text, std::shared_ptr<const void> owner,
                         std::shared_ptr<const MappedFile> mapping)
    : dialect_(dialect), fileName_(std::move(fileName)), fileIndex_(fileIndex), text_(text), owner_(std::move(owner)),
      mapping_(std::move(mapping)) {}

void ChunkSource::release(std::size_t from, std::size_t to) const {
    if (mapping_) {
        const auto textOffset = static_cast<std::size_t>(text_.data() - mapping_->bytes().data());
        mapping_->release(textOffset + from, textOffset + to);
    }
}

bool ChunkSource::reload(std::uint32_t chunk, std::span<Block> out, BlockStorage& storage) const {
    const Start& start = starts_[chunk];
    std::vector<Diagnostic> diagnostics; // said when the file was first parsed
    BlockParser parser(dialect_, storage, diagnostics, fileName_, fileIndex_);
    // Only the chunk's own text: a splitter looking for a line end that never comes would search
    // the rest of a large file for each chunk.
    LineSplitter lines(text_.substr(start.offset, start.end - start.offset));
    std::string_view line;
    std::uint32_t lineNumber = start.line;
    std::size_t filled = 0;
    bool same = true;
    while (filled < out.size() && lines.next(line)) {
        if (parser.parse(line, lineNumber, out[filled], lines.lineEnd())) {
            same = same && isPlainBlock(out[filled]);
            ++filled;
        }
        ++lineNumber;
    }
    release(start.offset, start.end);
    same = same && filled == out.size() && diagnostics.empty() && out[filled - 1].location.line == start.lastLine;
    if (!same) {
        // The file was edited or replaced while its program ran: every block of the chunk stops the
        // program where it is (Program::suspectMessage says why) instead of running other lines.
        Block stop;
        stop.location = {fileIndex_, start.line, 1};
        stop.suspect = true;
        std::fill(out.begin(), out.end(), stop);
    }
    return same;
}

} // namespace m350::gcode
