#pragma once

#include "core/gcode/BlockList.h"
#include "core/gcode/BlockStorage.h"
#include "core/gcode/Dialect.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

namespace m350::gcode {

class Program;

// Reads the second half of a large program's text on a second thread while the parser reads the
// first: a CAM program is mostly plain lines (`G1 X.. Y.. Z..`), which parse the same wherever
// they stand, so loading it takes about half the time on two cores.
//
// It starts at the first line after the middle of the text and takes plain lines as long as they
// come: it stops at the first line the plain-line parser declines (anything with macro syntax,
// O numbers, block delete, `/*`) and at a block that calls or ends a program (M98, G65, M30, M2,
// M99), whose meaning the parser's passes need. The parser, when it reaches that first line with
// no comment open, adopts the blocks and goes on from where the prefetch stopped; otherwise it
// parses as if there had been none, so the program is the same either way.
class PlainLinePrefetch {
public:
    // Starts reading `text` (which must outlive this) on a second thread. Null when the text has
    // no line that starts after its middle.
    static std::unique_ptr<PlainLinePrefetch> start(std::string_view text, const Dialect& dialect,
                                                    std::uint32_t fileIndex);
    ~PlainLinePrefetch(); // stops and joins the thread

    PlainLinePrefetch(const PlainLinePrefetch&) = delete;
    PlainLinePrefetch& operator=(const PlainLinePrefetch&) = delete;

    // Where the first line it reads starts in the text.
    std::size_t begin() const { return begin_; }

    // What it read, once the thread is done (take waits for it): the blocks of the lines from
    // begin() on, numbered as lines of the whole text; `end`, where the first line it did not take
    // starts; `linesBefore`, the lines before begin(), and `lines`, the lines it passed (blank
    // ones included); and its labelled blocks, as (label, index among its blocks). Nothing (no
    // line passed) when it failed.
    struct Result {
        BlockList blocks;
        std::size_t end = 0;
        std::uint32_t linesBefore = 0;
        std::uint32_t lines = 0;
        std::vector<std::pair<std::int32_t, std::uint32_t>> labels;
    };
    Result take();

    // Hands what the blocks refer to (their words and comments) to the program, which keeps it.
    void giveStorageTo(Program& program);

private:
    PlainLinePrefetch(std::string_view text, std::size_t begin, const Dialect& dialect, std::uint32_t fileIndex);
    void read();

    std::string_view text_;
    std::size_t begin_;
    const Dialect& dialect_;
    std::uint32_t fileIndex_;
    std::unique_ptr<BlockStorage> storage_ = std::make_unique<BlockStorage>();
    Result result_;
    std::exception_ptr failure_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

} // namespace m350::gcode
