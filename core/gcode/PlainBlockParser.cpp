#include "core/gcode/PlainBlockParser.h"

#include "core/gcode/DecimalScan.h"

#include <array>

namespace m350::gcode {

namespace {

bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

struct PlainWord {
    char letter;
    std::uint32_t letterColumn;
    double value;
};

} // namespace

PlainResult parsePlainBlock(std::string_view line, const Dialect& dialect, SourceLocation location,
                            BlockStorage& storage, Block& out) {
    constexpr std::size_t kMaxWords = 24;
    std::array<PlainWord, kMaxWords> found;
    std::size_t count = 0;
    const char* text = line.data();
    const std::size_t size = line.size();
    std::size_t i = 0;
    bool first = true;
    std::int32_t label = -1;
    std::uint32_t firstColumn = 0;
    std::string_view comment;
    auto skipSpaces = [&] {
        while (i < size && isSpace(text[i])) {
            ++i;
        }
    };
    // Columns equal byte offsets + 1 as long as everything before is ASCII; comments may hold other
    // characters, so the path declines a word that follows a non-ASCII comment.
    bool ascii = true;
    while (true) {
        skipSpaces();
        if (i >= size || text[i] == ';' ||
            (text[i] == '/' && i + 1 < size && text[i + 1] == '/' && dialect.slashSlashComments)) {
            break;
        }
        if (firstColumn == 0) {
            firstColumn = static_cast<std::uint32_t>(i + 1);
        }
        if (text[i] == '(') {
            std::size_t close = line.find(')', i);
            if (close == std::string_view::npos || !ascii) {
                return PlainResult::Declined;
            }
            for (std::size_t k = i; k < close; ++k) {
                ascii &= static_cast<unsigned char>(text[k]) < 0x80;
            }
            if (comment.empty()) {
                comment = line.substr(i + 1, close - i - 1);
            }
            i = close + 1;
            first = false;
            continue;
        }
        char letter = text[i];
        if (!isLetter(letter) || !ascii) {
            return PlainResult::Declined;
        }
        letter = static_cast<char>(letter & ~0x20); // upper case
        auto letterColumn = static_cast<std::uint32_t>(i + 1);
        ++i;
        skipSpaces();
        if (letter == 'O' || i >= size) {
            return PlainResult::Declined;
        }
        char sign = text[i];
        if (sign == '-' || sign == '+') {
            if (letter == 'N' && first) {
                return PlainResult::Declined;
            }
            ++i;
        } else {
            sign = 0;
        }
        bool digitFirst = i < size && text[i] >= '0' && text[i] <= '9';
        bool pointFirst = i + 1 < size && text[i] == '.' && text[i + 1] >= '0' && text[i + 1] <= '9';
        if (!digitFirst && !pointFirst) {
            return PlainResult::Declined;
        }
        double value = 0.0;
        if (!scanDecimal(text, size, i, value)) {
            return PlainResult::Declined;
        }
        if (i < size && ((!isSpace(text[i]) && !isLetter(text[i]) && text[i] != '(' && text[i] != ';' &&
                          text[i] != '/') ||
                         (text[i] | 0x20) == 'e')) {
            return PlainResult::Declined; // `P1E3` is an error the full parser explains
        }
        if (letter == 'N' && first && sign == 0) {
            if (value != static_cast<double>(static_cast<std::int64_t>(value)) || value > kMaxLabel) {
                return PlainResult::Declined;
            }
            label = static_cast<std::int32_t>(value);
            first = false;
            continue;
        }
        if (letter == 'N' || count == kMaxWords) {
            return PlainResult::Declined;
        }
        first = false;
        found[count++] = {letter, letterColumn, sign == '-' ? -value : value};
    }
    if (count == 0 && label < 0) {
        return PlainResult::Empty;
    }
    out.location = {location.file, location.line, firstColumn};
    out.label = label;
    if (!comment.empty()) {
        out.comment = storage.text.store(comment);
    }
    std::span<Word> room = storage.words.allocate(count);
    for (std::size_t k = 0; k < count; ++k) {
        Word& w = room[k];
        w.number = found[k].value;
        w.column = wordColumn(found[k].letterColumn);
        w.letter = found[k].letter;
        if (w.letter == 'M' && (w.number == 30 || w.number == 2)) {
            out.programEnd = true;
        }
    }
    out.words = room;
    return PlainResult::Parsed;
}

} // namespace m350::gcode
