#include "core/gcode/PlainBlockParser.h"

#include "core/gcode/DecimalScan.h"

#include <array>
#include <memory>

namespace m350::gcode {

namespace {

// What a character is to the fast path, looked up once instead of tested by ranges.
enum : std::uint8_t { kSpace = 1, kWordLetter = 2, kEndsNumber = 4, kLineEnd = 8 };
constexpr std::array<std::uint8_t, 256> kClasses = [] {
    std::array<std::uint8_t, 256> table{};
    table[' '] = table['\t'] = kSpace | kEndsNumber;
    // The line end after the line is where reading stops; inside a line (a caller's string) it is
    // a space.
    table['\r'] = table['\n'] = kLineEnd | kEndsNumber;
    for (int c = 'A'; c <= 'Z'; ++c) {
        table[static_cast<std::size_t>(c)] = kWordLetter | kEndsNumber;
        table[static_cast<std::size_t>(c + ('a' - 'A'))] = kWordLetter | kEndsNumber;
    }
    // N (a label, only first) and O (an O line) are not words here: they take the rare path.
    table['N'] = table['n'] = table['O'] = table['o'] = kEndsNumber;
    // What may follow a number: a space, a letter other than E (`P1E3` is an error the full parser
    // explains), a comment or a '/' (of `//`).
    table['E'] = table['e'] = kWordLetter;
    table['('] = table[';'] = table['/'] = kEndsNumber;
    return table;
}();

std::uint8_t classOf(const char* at) {
    return kClasses[static_cast<unsigned char>(*at)];
}

// Longer lines go to the general parser (no program line comes near it).
constexpr std::size_t kLongestPlainLine = 1024;
static_assert(kLongestPlainLine < kMaxWordColumn, "columns of plain lines are never clipped");
constexpr std::size_t kMostWords = 24;

// The value of a signed number starting at `at`, which must end a number (a space, a letter other
// than E, a comment): where it ends, or nullptr when it is not a plain number.
[[gnu::always_inline]] inline const char* scanSignedNumber(const char* at, double& value) {
    const bool negative = *at == '-';
    at = scanTerminatedDecimal(at + (negative || *at == '+' ? 1 : 0), value);
    if (at == nullptr || (classOf(at) & kEndsNumber) == 0) {
        return nullptr; // `P1E3` is an error the full parser explains
    }
    value = negative ? -value : value;
    return at;
}

} // namespace

PlainResult parsePlainLine(const char* text, const Dialect& dialect, SourceLocation location, BlockStorage& storage,
                           Block& out, std::size_t& length) {
    const char* at = text;
    auto skipSpaces = [&] {
        while ((classOf(at) & kSpace) != 0) {
            ++at;
        }
    };
    // The words go straight to the arena; they are kept only if the whole line is plain.
    Word* const words = storage.words.reserve(kMostWords);
    Word* nextWord = words;
    std::int32_t label = -1;
    bool programEnd = false;
    std::string_view comment;
    skipSpaces();
    const char* const firstItem = at;
    // Columns equal byte offsets + 1 as long as everything before is ASCII; comments may hold other
    // characters, so after a non-ASCII comment no letter starts a word and a word declines the line.
    std::uint8_t wordLetter = kWordLetter;
    while (true) {
        skipSpaces();
        // Most of what a line holds is a word: its letter is tested first.
        if ((classOf(at) & wordLetter) != 0) [[likely]] {
            const char* const letterAt = at;
            const auto letter = static_cast<char>(*at & ~0x20); // upper case
            ++at;
            skipSpaces();
            double value = 0.0;
            at = scanSignedNumber(at, value);
            if (at == nullptr || nextWord == words + kMostWords) {
                return PlainResult::Declined;
            }
            programEnd |= letter == 'M' && (value == 30 || value == 2);
            Word word;
            word.number = value;
            word.column = static_cast<std::uint32_t>(letterAt - text + 1);
            word.letter = letter;
            std::construct_at(nextWord, word);
            ++nextWord;
            continue;
        }
        if ((classOf(at) & kLineEnd) != 0) {
            break;
        }
        if (at == firstItem && (*at | 0x20) == 'n') {
            // Only a first unsigned whole N number is a label; the full parser explains the rest.
            ++at;
            skipSpaces();
            double value = 0.0;
            at = *at == '-' || *at == '+' ? nullptr : scanSignedNumber(at, value);
            if (at == nullptr || value != static_cast<double>(static_cast<std::int64_t>(value)) || value > kMaxLabel) {
                return PlainResult::Declined;
            }
            label = static_cast<std::int32_t>(value);
            continue;
        }
        if (*at == ';' || (*at == '/' && at[1] == '/' && dialect.slashSlashComments)) {
            while ((classOf(at) & kLineEnd) == 0) {
                ++at;
            }
            break;
        }
        if (*at != '(' || wordLetter == 0) {
            return PlainResult::Declined;
        }
        const char* closing = at + 1;
        for (; *closing != ')'; ++closing) {
            if ((classOf(closing) & kLineEnd) != 0) {
                return PlainResult::Declined; // not closed on its line
            }
            if (*closing == '(') {
                return PlainResult::Declined; // a nested '(': the general parser says where it ends
            }
            wordLetter = static_cast<unsigned char>(*closing) < 0x80 ? wordLetter : 0;
        }
        if (comment.empty()) {
            comment = std::string_view(at + 1, static_cast<std::size_t>(closing - at - 1));
        }
        at = closing + 1;
    }
    length = static_cast<std::size_t>(at - text);
    if (length > kLongestPlainLine) {
        return PlainResult::Declined;
    }
    const auto count = static_cast<std::size_t>(nextWord - words);
    if (count == 0 && label < 0) {
        return PlainResult::Empty;
    }
    // Copied from a made block: cheaper than setting each field's default one by one.
    static constexpr Block kPlainBlock{};
    Block& block = *std::construct_at(&out, kPlainBlock);
    block.location = {location.file, location.line, static_cast<std::uint32_t>(firstItem - text + 1)};
    block.label = label;
    block.programEnd = programEnd;
    if (!comment.empty()) {
        block.comment = storage.text.store(comment);
    }
    block.words = storage.words.keep(count);
    return PlainResult::Parsed;
}

PlainResult parsePlainBlock(std::string_view line, const Dialect& dialect, SourceLocation location,
                            BlockStorage& storage, Block& out, LineEnd lineEnd) {
    if (line.size() > kLongestPlainLine) {
        return PlainResult::Declined;
    }
    std::size_t length = 0;
    if (lineEnd == LineEnd::Follows) {
        return parsePlainLine(line.data(), dialect, location, storage, out, length);
    }
    // A copy with a line end after it; a caller's line end inside the line is for the full parser.
    std::array<char, kLongestPlainLine + 1> copy;
    for (std::size_t i = 0; i < line.size(); ++i) {
        copy[i] = line[i];
        if ((classOf(&copy[i]) & kLineEnd) != 0) {
            return PlainResult::Declined;
        }
    }
    copy[line.size()] = '\n';
    return parsePlainLine(copy.data(), dialect, location, storage, out, length);
}

} // namespace m350::gcode
