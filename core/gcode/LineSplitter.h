#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>

namespace m350::gcode {

// Splits program text into lines at LF, CRLF and a lone CR (old Mac files and some panel exports
// end lines with CR alone). A text with n line ends has n + 1 lines, the last one possibly empty,
// so line numbers agree with an editor's. Each line end is searched for once (memchr), so a file
// of CR-only lines costs no more than one of LF lines.
class LineSplitter {
public:
    explicit LineSplitter(std::string_view text) : text_(text) {}

    // The next line, without its line end; false after the last line.
    bool next(std::string_view& line) {
        if (done_) {
            return false;
        }
        const std::size_t lf = find('\n', lf_);
        const std::size_t cr = find('\r', cr_);
        const std::size_t end = lf < cr ? lf : cr;
        line = text_.substr(start_, end - start_);
        if (end == text_.size()) {
            done_ = true;
            return true;
        }
        start_ = end + 1 + (end == cr && cr + 1 == lf && lf < text_.size() ? 1 : 0); // CRLF: one line end
        return true;
    }

    // Where the line last returned starts in the text.
    std::size_t lineStart(std::string_view line) const { return static_cast<std::size_t>(line.data() - text_.data()); }

private:
    // The first `c` at or after the current line's start; `cached` keeps the last answer while it is
    // still ahead.
    std::size_t find(char c, std::size_t& cached) {
        if (cached >= start_ && cached != kUnknown) {
            return cached;
        }
        if (start_ >= text_.size()) {
            return cached = text_.size();
        }
        const void* found = std::memchr(text_.data() + start_, c, text_.size() - start_);
        cached = found ? static_cast<std::size_t>(static_cast<const char*>(found) - text_.data()) : text_.size();
        return cached;
    }

    static constexpr std::size_t kUnknown = static_cast<std::size_t>(-1);
    std::string_view text_;
    std::size_t start_ = 0;
    std::size_t lf_ = kUnknown;
    std::size_t cr_ = kUnknown;
    bool done_ = false;
};

} // namespace m350::gcode
