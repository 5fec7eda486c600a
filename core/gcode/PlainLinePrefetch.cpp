#include "core/gcode/PlainLinePrefetch.h"

#include "core/gcode/LineSplitter.h"
#include "core/gcode/PlainBlockParser.h"
#include "core/gcode/Program.h"
#include "core/gcode/WordFacts.h"

#include <algorithm>
#include <cstring>
#include <system_error>

namespace m350::gcode {

std::unique_ptr<PlainLinePrefetch> PlainLinePrefetch::start(std::string_view text, const Dialect& dialect,
                                                            std::uint32_t fileIndex) {
    // The parser's own half takes it a little longer per line (it also indexes what it reads),
    // so the second thread starts a little before the middle.
    const std::size_t newline = text.find('\n', text.size() / 100 * 46);
    if (newline == std::string_view::npos || newline + 1 >= text.size()) {
        return nullptr;
    }
    std::unique_ptr<PlainLinePrefetch> prefetch(new PlainLinePrefetch(text, newline + 1, dialect, fileIndex));
    try {
        prefetch->thread_ = std::thread([p = prefetch.get()] { p->read(); });
    } catch (const std::system_error&) {
        return nullptr; // no thread to be had (a process or memory limit): the parser reads it all
    }
    return prefetch;
}

PlainLinePrefetch::PlainLinePrefetch(std::string_view text, std::size_t begin, const Dialect& dialect,
                                     std::uint32_t fileIndex)
    : text_(text), begin_(begin), dialect_(dialect), fileIndex_(fileIndex) {
    result_.end = begin;
}

PlainLinePrefetch::~PlainLinePrefetch() {
    stop_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) {
        thread_.join();
    }
}

namespace {

// The lines before `end` as the parser counts them: each LF, CRLF and lone CR ends one.
std::uint32_t linesBefore(std::string_view text, std::size_t end) {
    // A loop the compiler vectorizes (std::count is not): it runs before the thread's first line.
    const char* data = text.data();
    std::uint32_t count = 0;
    for (std::size_t i = 0; i < end; ++i) {
        count += data[i] == '\n' ? 1u : 0u;
    }
    for (const char* cr = data; (cr = static_cast<const char*>(std::memchr(cr, '\r', static_cast<std::size_t>(data + end - cr)))) != nullptr; ++cr) {
        count += cr + 1 < data + text.size() && cr[1] == '\n' ? 0 : 1;
    }
    return count;
}

} // namespace

void PlainLinePrefetch::read() {
    try {
        const std::uint32_t before = linesBefore(text_, begin_);
        result_.linesBefore = before;
        // Lines are passed as the parser passes them; the last line (no line end after it) is left
        // to the parser.
        LineSplitter lines(text_.substr(begin_));
        std::uint32_t number = 0;
        BlockList& blocks = result_.blocks;
        blocks.expectMany();
        storage_->words.expectMany();
        while (!stop_.load(std::memory_order_relaxed) && lines.lineAhead() != nullptr) {
            Block& block = blocks.nextSlot();
            std::size_t length = 0;
            const PlainResult read = parsePlainLine(lines.lineAhead(), dialect_, {fileIndex_, before + number + 1, 0},
                                                    *storage_, block, length);
            if (read == PlainResult::Declined) {
                break;
            }
            if (read == PlainResult::Parsed) {
                const WordFacts facts = wordFacts(block);
                if (facts.call || facts.ends || block.programEnd || block.suspect) {
                    break;
                }
                if (block.label >= 0) {
                    result_.labels.emplace_back(block.label, static_cast<std::uint32_t>(blocks.size()));
                }
                blocks.addNextSlot();
            }
            lines.skipLine(length);
            ++number;
            result_.end = begin_ + lines.position();
            result_.lines = number;
        }
    } catch (...) {
        failure_ = std::current_exception();
    }
}

PlainLinePrefetch::Result PlainLinePrefetch::take() {
    if (thread_.joinable()) {
        thread_.join();
    }
    if (failure_) {
        return {}; // out of memory, most likely: the parser reads these lines itself
    }
    return std::move(result_);
}

void PlainLinePrefetch::giveStorageTo(Program& program) {
    program.adoptedStorage.push_back(std::move(storage_));
    storage_ = std::make_unique<BlockStorage>();
}

} // namespace m350::gcode
