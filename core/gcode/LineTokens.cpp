#include "core/gcode/LineTokens.h"

#include "core/common/Message.h"

#include <algorithm>

namespace m350::gcode {

void LineTokens::read(const Lexer& lexer, std::string_view line, BlockCommentState& comment) {
    line_ = line;
    columnCacheOffset_ = 0;
    columnCacheColumn_ = 1;
    lexer.tokenize(line, tokens_, comment);
    const Token end = tokens_.back();
    tokens_.insert(tokens_.end(), kLookahead, end);
    position_ = 0;
}

std::string LineTokens::describe(const Token& token) const {
    switch (token.kind) {
    case TokenKind::End: return "the end of the line";
    case TokenKind::Comment: return "a comment";
    default: return "'" + source(token) + "'";
    }
}

std::string LineTokens::describeWords(const Token& token) const {
    switch (token.kind) {
    case TokenKind::End: return bilingual("the end of the line", "行尾");
    case TokenKind::Comment: return bilingual("a comment", "注释");
    default: return "'" + source(token) + "'";
    }
}

// Columns count characters: comments before the statement may hold multi-byte ones.
std::uint32_t LineTokens::columnAt(std::size_t offset) const {
    offset = std::min(offset, line_.size());
    if (offset < columnCacheOffset_) {
        columnCacheOffset_ = 0;
        columnCacheColumn_ = 1;
    }
    for (std::size_t i = columnCacheOffset_; i < offset; ++i) {
        columnCacheColumn_ += (static_cast<unsigned char>(line_[i]) & 0xC0) != 0x80 ? 1 : 0;
    }
    columnCacheOffset_ = offset;
    return columnCacheColumn_;
}

bool LineTokens::startsLabelled() const {
    if (tokens_.empty()) {
        return false;
    }
    std::size_t i = 0;
    while (tokens_[i].kind == TokenKind::Comment) {
        ++i;
    }
    i += tokens_[i].kind == TokenKind::Slash ? 1 : 0;
    return tokens_[i].kind == TokenKind::Letter && (tokens_[i].letter == 'N' || tokens_[i].letter == 'O');
}

} // namespace m350::gcode
