#include "core/gcode/PlainBlockParser.h"

#include "core/gcode/DecimalScan.h"

#include <array>

namespace m350::gcode {

namespace {

// What a character is to the fast path, looked up once instead of tested by ranges.
enum : std::uint8_t { kSpace = 1, kLetter = 2, kEndsNumber = 4 };
constexpr std::array<std::uint8_t, 256> kClasses = [] {
    std::array<std::uint8_t, 256> table{};
    for (char c : {' ', '\t', '\r', '\n'}) {
        table[static_cast<unsigned char>(c)] = kSpace | kEndsNumber;
    }
    for (int c = 'A'; c <= 'Z'; ++c) {
        table[static_cast<std::size_t>(c)] = kLetter | kEndsNumber;
        table[static_cast<std::size_t>(c + ('a' - 'A'))] = kLetter | kEndsNumber;
    }
    // What may follow a number: a space, a letter other than E (`P1E3` is an error the full parser
    // explains), a comment or a '/' (of `//`).
    table['E'] = table['e'] = kLetter;
    table['('] = table[';'] = table['/'] = kEndsNumber;
    return table;
}();

bool isLetter(char c) {
    return (kClasses[static_cast<unsigned char>(c)] & kLetter) != 0;
}
bool isSpace(char c) {
    return (kClasses[static_cast<unsigned char>(c)] & kSpace) != 0;
}
bool isDigit(char c) {
    return static_cast<unsigned>(c - '0') < 10u;
}
bool endsNumber(char c) {
    return (kClasses[static_cast<unsigned char>(c)] & kEndsNumber) != 0;
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
    bool programEnd = false;
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
        if (i >= size) {
            break;
        }
        if (firstColumn == 0) {
            firstColumn = static_cast<std::uint32_t>(i + 1);
        }
        char letter = text[i];
        // Most of what a line holds is a word: its letter is tested first.
        if (!isLetter(letter)) {
            if (letter == ';' || (letter == '/' && i + 1 < size && text[i + 1] == '/' && dialect.slashSlashComments)) {
                break;
            }
            if (letter != '(') {
                return PlainResult::Declined;
            }
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
        if (!ascii) {
            return PlainResult::Declined;
        }
        letter = static_cast<char>(letter & ~0x20); // upper case
        const auto letterColumn = static_cast<std::uint32_t>(i + 1);
        ++i;
        skipSpaces();
        if (letter == 'O' || i >= size) {
            return PlainResult::Declined;
        }
        const char sign = text[i];
        const bool negative = sign == '-';
        if (negative || sign == '+') {
            if (letter == 'N' && first) {
                return PlainResult::Declined;
            }
            ++i;
        }
        const bool digitFirst = i < size && isDigit(text[i]);
        if (!digitFirst && !(i + 1 < size && text[i] == '.' && isDigit(text[i + 1]))) {
            return PlainResult::Declined;
        }
        double value = 0.0;
        if (!scanDecimal(text, size, i, value)) {
            return PlainResult::Declined;
        }
        if (i < size && !endsNumber(text[i])) {
            return PlainResult::Declined; // `P1E3` is an error the full parser explains
        }
        if (letter == 'N') {
            const bool unsignedLabel = first && sign != '-' && sign != '+';
            if (!unsignedLabel || value != static_cast<double>(static_cast<std::int64_t>(value)) ||
                value > kMaxLabel) {
                return PlainResult::Declined;
            }
            label = static_cast<std::int32_t>(value);
            first = false;
            continue;
        }
        if (count == kMaxWords) {
            return PlainResult::Declined;
        }
        first = false;
        if (negative) {
            value = -value;
        }
        if (letter == 'M' && (value == 30 || value == 2)) {
            programEnd = true;
        }
        found[count++] = {letter, letterColumn, value};
    }
    if (count == 0 && label < 0) {
        return PlainResult::Empty;
    }
    out.location = {location.file, location.line, firstColumn};
    out.label = label;
    out.programEnd = programEnd;
    if (!comment.empty()) {
        out.comment = storage.text.store(comment);
    }
    std::span<Word> room = storage.words.allocate(count);
    for (std::size_t k = 0; k < count; ++k) {
        Word& w = room[k];
        w.number = found[k].value;
        w.column = wordColumn(found[k].letterColumn);
        w.letter = found[k].letter;
    }
    out.words = room;
    return PlainResult::Parsed;
}

} // namespace m350::gcode
