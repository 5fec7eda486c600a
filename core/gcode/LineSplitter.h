#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string_view>

namespace m350::gcode {

// Whether the byte just past a line is readable and a line end ('\n' or '\r'), as it is for every
// line a LineSplitter gives but the last: the plain-line parser then reads the line in place.
enum class LineEnd { Unknown, Follows };

// Splits program text into lines at LF, CRLF and a lone CR (old Mac files and some panel exports
// end lines with CR alone). A text with n line ends has n + 1 lines, the last one possibly empty,
// so line numbers agree with an editor's. Each byte is searched for each line end once (memchr),
// so a file of CR-only lines costs no more than one of LF lines; and the search never runs more
// than a window past the line it ends, so the pages of a large mapped program that the parser
// has not reached stay untouched.
class LineSplitter {
public:
    explicit LineSplitter(std::string_view text) : text_(text), lineEndsBefore_(pastLastLineEnd(text)) {}

    // The next line, without its line end; false after the last line.
    bool next(std::string_view& line) {
        if (done_) {
            return false;
        }
        std::size_t window = start_;
        std::size_t lf = kNone;
        std::size_t cr = kNone;
        do {
            window = text_.size() - window > kWindow ? window + kWindow : text_.size();
            lf = first('\n', lf_, window);
            cr = first('\r', cr_, lf == kNone ? window : lf + 1);
        } while (lf == kNone && cr == kNone && window < text_.size());
        const std::size_t end = std::min({lf, cr, text_.size()});
        line = text_.substr(start_, end - start_);
        if (end == text_.size()) {
            done_ = true;
            return true;
        }
        const bool crlf = end == cr && end + 1 < text_.size() && text_[end + 1] == '\n';
        start_ = end + (crlf ? 2 : 1);
        return true;
    }

    // Where the next line starts, when a line end follows it in the text (nullptr otherwise): it
    // may then be read in place up to its line end, and passed with skipLine.
    const char* lineAhead() const { return start_ < lineEndsBefore_ ? text_.data() + start_ : nullptr; }
    // Passes the line lineAhead() pointed to, `length` bytes up to its line end, as next() gives it.
    std::string_view skipLine(std::size_t length) {
        const std::size_t end = start_ + length;
        const std::string_view line(text_.data() + start_, length);
        const bool crlf = text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n';
        start_ = end + (crlf ? 2 : 1);
        return line;
    }

    // Where the next line starts; seek() makes the line that starts at `offset` the next one.
    std::size_t position() const { return start_; }
    void seek(std::size_t offset) {
        start_ = offset;
        done_ = false;
    }

    // Whether the line last returned is followed by its line end in the text (all but the last).
    LineEnd lineEnd() const { return done_ ? LineEnd::Unknown : LineEnd::Follows; }

    // Where the line last returned starts in the text.
    std::size_t lineStart(std::string_view line) const { return static_cast<std::size_t>(line.data() - text_.data()); }

private:
    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    static constexpr std::size_t kWindow = std::size_t{64} << 10;

    // What is known of one line end ahead: none in [line start, searched) but at `found`.
    struct Search {
        std::size_t found = kNone;
        std::size_t searched = 0;
    };

    // The first `c` in [start_, limit), or kNone. The search reaches a window past `limit`, so the
    // next lines' questions are mostly answered without another search.
    std::size_t first(char c, Search& s, std::size_t limit) {
        if (s.found != kNone && s.found >= start_) {
            return s.found < limit ? s.found : kNone;
        }
        const std::size_t from = std::max(s.searched, start_);
        if (from >= limit) {
            return kNone;
        }
        const std::size_t extent = std::min(text_.size(), std::max(limit, from + kWindow));
        const void* at = std::memchr(text_.data() + from, c, extent - from);
        if (at == nullptr) {
            s.searched = extent;
            return kNone;
        }
        s.found = static_cast<std::size_t>(static_cast<const char*>(at) - text_.data());
        s.searched = s.found + 1;
        return s.found < limit ? s.found : kNone;
    }

    static std::size_t pastLastLineEnd(std::string_view text) {
        std::size_t i = text.size();
        while (i > 0 && text[i - 1] != '\n' && text[i - 1] != '\r') {
            --i;
        }
        return i;
    }

    std::string_view text_;
    std::size_t lineEndsBefore_; // one past the text's last line end, 0 when it has none
    std::size_t start_ = 0;
    Search lf_;
    Search cr_;
    bool done_ = false;
};

} // namespace m350::gcode
