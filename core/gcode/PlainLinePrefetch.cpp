#include "core/gcode/PlainLinePrefetch.h"

#include "core/gcode/LineSplitter.h"
#include "core/gcode/PlainBlockParser.h"
#include "core/gcode/Program.h"
#include "core/gcode/WordFacts.h"

namespace m350::gcode {

std::unique_ptr<PlainLinePrefetch> PlainLinePrefetch::start(std::string_view text, const Dialect& dialect,
                                                            std::uint32_t fileIndex) {
    // The parser's own half takes it a little longer per line (it also indexes what it reads),
    // so the second thread starts a little before the middle.
    const std::size_t newline = text.find('\n', text.size() / 100 * 48);
    if (newline == std::string_view::npos || newline + 1 >= text.size()) {
        return nullptr;
    }
    std::unique_ptr<PlainLinePrefetch> prefetch(new PlainLinePrefetch(text, newline + 1, dialect, fileIndex));
    prefetch->thread_ = std::thread([p = prefetch.get()] { p->read(); });
    return prefetch;
}

PlainLinePrefetch::PlainLinePrefetch(std::string_view text, std::size_t begin, const Dialect& dialect,
                                     std::uint32_t fileIndex)
    : text_(text), begin_(begin), dialect_(dialect), fileIndex_(fileIndex), end_(begin) {}

PlainLinePrefetch::~PlainLinePrefetch() {
    stop_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) {
        thread_.join();
    }
}

void PlainLinePrefetch::read() {
    try {
        // Lines are passed as the parser passes them; the last line (no line end after it) is left
        // to the parser.
        LineSplitter lines(text_.substr(begin_));
        std::uint32_t number = 0;
        while (!stop_.load(std::memory_order_relaxed) && lines.lineAhead() != nullptr) {
            Block& block = blocks_.nextSlot();
            std::size_t length = 0;
            const PlainResult result =
                parsePlainLine(lines.lineAhead(), dialect_, {fileIndex_, number + 1, 0}, *storage_, block, length);
            if (result == PlainResult::Declined) {
                break;
            }
            if (result == PlainResult::Parsed) {
                const WordFacts facts = wordFacts(block);
                if (facts.call || facts.ends || block.programEnd || block.suspect) {
                    break;
                }
                blocks_.addNextSlot();
            }
            lines.skipLine(length);
            ++number;
            end_ = begin_ + lines.position();
            lines_ = number;
        }
    } catch (...) {
        failure_ = std::current_exception();
    }
}

PlainLinePrefetch::Result PlainLinePrefetch::finish() {
    if (thread_.joinable()) {
        thread_.join();
    }
    if (failure_) {
        return {nullptr, begin_, 0}; // out of memory, most likely: the parser reads these lines itself
    }
    return {&blocks_, end_, lines_};
}

void PlainLinePrefetch::giveStorageTo(Program& program) {
    program.adoptedStorage.push_back(std::move(storage_));
    storage_ = std::make_unique<BlockStorage>();
}

} // namespace m350::gcode
