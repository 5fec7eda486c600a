#include "core/files/TomlScreen.h"

#include <cstdio>
#include <vector>

namespace m350::files {

namespace {

bool isAsciiSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Where toml++ reads a quote as opening a string. A string starts a key or a value; a value that
// starts with anything else is read bare up to a terminator (whitespace , ] } #), quotes included,
// and toml++ tests each of its characters for whitespace (`a = 5"é"`, `a = 1."é"`). So the syntax
// around a quote is followed: keys or values, and the open arrays, inline tables and table header.
class TomlContext {
public:
    bool quoteOpensString() const { return !bare_; }
    void afterString() { bare_ = false; }

    // One character outside strings and comments ('#' for a whole comment).
    void step(char c) {
        switch (c) {
        case ' ':
        case '\t':
        case '\r':
        case '#': bare_ = false; return;
        case '\n':
            bare_ = false;
            while (!open_.empty() && open_.back() == 'h') open_.pop_back();
            key_ = open_.empty() || open_.back() == '{';
            return;
        case ',':
            bare_ = false;
            key_ = !open_.empty() && open_.back() == '{';
            return;
        case ']':
        case '}':
            bare_ = false;
            if (!open_.empty() && (c == '}' ? open_.back() == '{' : open_.back() != '{')) open_.pop_back();
            key_ = false;
            return;
        default: break;
        }
        if (bare_) return;
        if (key_) {
            if (c == '=') key_ = false;
            if (c == '[' && open_.empty()) open_.push_back('h');
            return;
        }
        if (c == '[') {
            open_.push_back('[');
        } else if (c == '{') {
            open_.push_back('{');
            key_ = true;
        } else {
            bare_ = true;
        }
    }

private:
    std::vector<char> open_; // '[' an array, '{' an inline table, 'h' a table header
    bool key_ = true;        // a key comes next, or goes on; else a value
    bool bare_ = false;      // inside a value read bare
};

// Walks the text as toml++ will, one code point at a time, counting lines and columns.
class Screen {
public:
    explicit Screen(std::string_view text) : text_(text) {}

    std::optional<TomlRefusal> run() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
            advance(); // a byte-order mark opening the text is read as such
        }
        TomlContext context;
        while (!done()) {
            const char c = peek();
            const bool quote = (c == '"' || c == '\'') && context.quoteOpensString();
            if (c == '#') {
                skipComment();
                context.step('#');
            } else if (quote) {
                if (auto refused = skipString(c)) return refused;
                context.afterString();
            } else if (static_cast<unsigned char>(c) >= 0x80) {
                return refuse(describe() + " may only stand inside a string or a comment" + hint());
            } else {
                advance();
                context.step(c);
            }
        }
        return std::nullopt;
    }

private:
    bool done() const { return at_ >= text_.size(); }
    char peek() const { return text_[at_]; }
    bool startsWith(std::string_view s) const { return text_.substr(at_, s.size()) == s; }

    // Moves past one code point (a malformed UTF-8 byte counts as one).
    void advance() {
        if (text_[at_] == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        ++at_;
        while (!done() && (static_cast<unsigned char>(text_[at_]) & 0xC0) == 0x80) {
            ++at_;
        }
    }

    void advanceBy(std::size_t codePoints) {
        for (std::size_t i = 0; i < codePoints && !done(); ++i) advance();
    }

    // The code point at the cursor, or -1 where the bytes are not UTF-8.
    long codePoint() const {
        const auto lead = static_cast<unsigned char>(text_[at_]);
        const int length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
        if (lead < 0x80) return lead;
        if (length == 1 || lead > 0xF4 || at_ + length > text_.size()) return -1;
        long code = lead & (0x3F >> (length - 1));
        for (int i = 1; i < length; ++i) {
            const auto byte = static_cast<unsigned char>(text_[at_ + i]);
            if ((byte & 0xC0) != 0x80) return -1;
            code = (code << 6) | (byte & 0x3F);
        }
        return code;
    }

    std::string describe() const {
        const long code = codePoint();
        char name[48];
        if (code < 0) {
            std::snprintf(name, sizeof name, "byte 0x%02X, which is not UTF-8,",
                          static_cast<unsigned>(static_cast<unsigned char>(text_[at_])));
            return name;
        }
        std::snprintf(name, sizeof name, "U+%04lX", code);
        return "character '" + std::string(text_.substr(at_, code < 0x800 ? 2 : code < 0x10000 ? 3 : 4)) + "' (" +
               name + ")";
    }

    std::string hint() const {
        switch (codePoint()) {
        case 0x3000: return ": a full-width space; type an ASCII space instead";
        case 0x00A0: return ": a no-break space; type an ASCII space instead";
        case 0xFEFF: return ": a byte-order mark belongs only at the very start of the file";
        default: return "";
        }
    }

    std::optional<TomlRefusal> skipString(char quote) {
        if (quote == '"' && startsWith("\"\"\"")) return multiLineBasicString();
        if (quote == '\'' && startsWith("'''")) {
            multiLineLiteralString();
        } else {
            singleLineString(quote);
        }
        return std::nullopt;
    }

    TomlRefusal refuse(std::string message) const { return TomlRefusal{line_, column_, std::move(message)}; }

    void skipComment() {
        while (!done() && peek() != '\n') advance();
    }

    // Up to and including the closing quote; an unterminated string ends at its line, as toml++ says.
    void singleLineString(char quote) {
        advance();
        while (!done() && peek() != quote && peek() != '\n') {
            if (quote == '"' && peek() == '\\') advance();
            if (!done() && peek() != '\n') advance();
        }
        if (!done() && peek() == quote) advance();
    }

    // A closing delimiter may be followed by up to two more quotes, which belong to the string.
    void closeMultiLine(char quote) {
        advanceBy(3);
        for (int extra = 0; extra < 2 && !done() && peek() == quote; ++extra) advance();
    }

    void multiLineLiteralString() {
        advanceBy(3);
        while (!done() && !startsWith("'''")) advance();
        if (!done()) closeMultiLine('\'');
    }

    std::optional<TomlRefusal> multiLineBasicString() {
        advanceBy(3);
        while (!done() && !startsWith("\"\"\"")) {
            if (peek() != '\\') {
                advance();
                continue;
            }
            advance();
            if (done()) break;
            if (static_cast<unsigned char>(peek()) >= 0x80) {
                return refuse(describe() + " cannot follow a backslash (an escape is \\n, \\t, \\uXXXX ...)");
            }
            if (!isAsciiSpace(peek())) {
                advance(); // an escaped character, '"' and '\' included
                continue;
            }
            while (!done() && isAsciiSpace(peek())) advance();
            if (!done() && static_cast<unsigned char>(peek()) >= 0x80) {
                return refuse("after a line-ending backslash the text must go on with an ASCII character, not " +
                              describe());
            }
        }
        if (!done()) closeMultiLine('"');
        return std::nullopt;
    }

    std::string_view text_;
    std::size_t at_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace

std::optional<TomlRefusal> findCharacterTomlCannotRead(std::string_view text) { return Screen(text).run(); }

} // namespace m350::files
