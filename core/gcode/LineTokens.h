#pragma once

#include "core/gcode/Lexer.h"
#include "core/gcode/Token.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace m350::gcode {

// The line the parser reads, as tokens, and how far it has read them: what it peeks at, takes,
// goes back to, and quotes of the line in its messages (a token's text, a byte's column).
class LineTokens {
public:
    static constexpr int kLookahead = 2; // peek(1) and peek(2) are the farthest the grammar looks

    // Tokenizes `line` (with the comment left open by the line before) and starts at its first
    // token. The list ends with kLookahead End tokens after its own, so peeking never runs past it
    // and next() never moves beyond the first End.
    void read(const Lexer& lexer, std::string_view line, BlockCommentState& comment);

    const Token& peek(std::size_t ahead = 0) const { return tokens_[position_ + ahead]; }
    const Token& next() {
        const Token& t = tokens_[position_];
        position_ += t.kind != TokenKind::End ? 1 : 0;
        return t;
    }
    bool atKeyword(Keyword k) const { return peek().kind == TokenKind::Keyword && peek().keyword == k; }
    std::size_t position() const { return position_; }
    void moveTo(std::size_t position) { position_ = position; }

    // Every token, the End tokens after the line's own included.
    std::size_t size() const { return tokens_.size(); }
    bool empty() const { return tokens_.empty(); }
    const Token& operator[](std::size_t index) const { return tokens_[index]; }
    std::vector<Token>::const_iterator begin() const { return tokens_.begin(); }
    std::vector<Token>::const_iterator end() const { return tokens_.end(); }

    std::string_view line() const { return line_; }
    // The token's text as written.
    std::string source(const Token& token) const { return std::string(line_.substr(token.offset, token.length)); }
    // What a message calls the token: its text in quotes, "the end of the line", "a comment".
    std::string describe(const Token& token) const;
    // describe() as a message's argument: the words in both languages.
    std::string describeWords(const Token& token) const;
    // The column (characters, not UTF-8 bytes) of the byte at `offset`.
    std::uint32_t columnAt(std::size_t offset) const;
    // Whether the line begins with an N or O number (after comments and a block delete).
    bool startsLabelled() const;

private:
    std::string_view line_;
    std::vector<Token> tokens_;
    std::size_t position_ = 0;
    // columnAt's last answer: DPRNT asks for one column per item, left to right, so each call
    // counts on from the last instead of from the line's start (a 100,000-item DPRNT was quadratic)
    mutable std::size_t columnCacheOffset_ = 0;
    mutable std::uint32_t columnCacheColumn_ = 1;
};

} // namespace m350::gcode
