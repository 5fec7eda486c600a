#include "ui/program/GcodeSyntax.h"

#include "core/gcode/Dialect.h"
#include "core/gcode/LexerText.h"

#include <QLatin1StringView>

#include <array>

namespace m350::ui {

namespace {

using Kind = GcodeSyntax::Kind;

constexpr std::array kKeywords{"IF", "GOTO", "GO", "TO", "WHILE", "DO", "END", "THEN", "AND", "OR", "XOR",
                               "MOD", "EQ", "NE", "LT", "GT", "LE", "GE"};
constexpr std::array kFunctions{"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "BIN", "BCD",
                                "ROUND", "FIX", "FUP", "LN", "EXP", "POW"};

bool isLetter(QChar c) { return (c >= u'A' && c <= u'Z') || (c >= u'a' && c <= u'z'); }
bool isDigit(QChar c) { return c >= u'0' && c <= u'9'; }

template <std::size_t N> bool among(const std::array<const char*, N>& names, QStringView word, bool upperOnly) {
    for (const char* name : names) {
        if (word.compare(QLatin1StringView(name), upperOnly ? Qt::CaseSensitive : Qt::CaseInsensitive) == 0) {
            return true;
        }
    }
    return false;
}

int skipNumber(QStringView line, int i) {
    while (i < line.size() && (isDigit(line[i]) || line[i] == u'.')) {
        ++i;
    }
    return i;
}

} // namespace

GcodeSyntax::GcodeSyntax(const gcode::Dialect& dialect)
    : m350_(dialect.slashSlashComments), blockComments_(dialect.blockComments),
      upperOnly_(dialect.upperCaseKeywords) {}

bool GcodeSyntax::blockCommentAfter(QStringView line, bool inBlockComment) const {
    if (!blockComments_ || (!inBlockComment && !line.contains(u"/*"))) {
        return inBlockComment;
    }
    std::vector<Span> spans;
    return scan(line, inBlockComment, spans);
}

bool GcodeSyntax::scan(QStringView line, bool inBlockComment, std::vector<Span>& out) const {
    out.clear();
    const int n = static_cast<int>(line.size());
    bool messageNext = false; // after `#1503 =` / `#1505 =` the parenthesised text is the message
    int i = 0;
    while (i < n) {
        if (inBlockComment) {
            qsizetype close = line.indexOf(u"*/", i);
            int end = close < 0 ? n : static_cast<int>(close) + 2;
            out.push_back({i, end - i, Kind::Comment});
            inBlockComment = close < 0;
            i = end;
            continue;
        }
        const QChar c = line[i];
        const QChar next = i + 1 < n ? line[i + 1] : QChar();
        if (c == u';' || (m350_ && c == u'/' && next == u'/')) {
            out.push_back({i, n - i, Kind::Comment});
            break;
        }
        if (blockComments_ && c == u'/' && next == u'*') {
            inBlockComment = true;
            continue;
        }
        if (c == u'(') {
            qsizetype close = line.indexOf(u')', i);
            int end = close < 0 ? n : static_cast<int>(close) + 1;
            out.push_back({i, end - i, messageNext ? Kind::Message : Kind::Comment});
            messageNext = false;
            i = end;
            continue;
        }
        if (c == u'#') {
            int end = skipNumber(line, i + 1);
            out.push_back({i, end - i, Kind::Variable});
            QStringView number = line.sliced(i + 1, end - i - 1);
            if (m350_ && (number == u"1503" || number == u"1505")) {
                messageNext = true;
            }
            i = end;
            continue;
        }
        if (isDigit(c) || (c == u'.' && isDigit(next))) {
            int end = skipNumber(line, i);
            out.push_back({i, end - i, Kind::Number});
            i = end;
            continue;
        }
        if (isLetter(c)) {
            i = word(line, i, out);
            continue;
        }
        ++i;
    }
    return inBlockComment;
}

// Keywords written together, as the parser splits them: `LEABS` in `IF[#10LEABS[#11]]`.
bool GcodeSyntax::packedKeywords(QStringView letters, int start, std::vector<Span>& out) const {
    if (letters.size() > 16 || (upperOnly_ && letters != letters.toString().toUpper())) {
        return false;
    }
    const std::string upper = letters.toString().toUpper().toStdString();
    gcode::KeywordSplit split = gcode::splitKeywords(upper);
    for (std::size_t part = 0; part < split.count; ++part) {
        const int length = split.length[part];
        const bool function = gcode::isFunctionKeyword(split.keyword[part]);
        out.push_back({start, length, function ? Kind::Function : Kind::Keyword});
        start += length;
    }
    return split.count != 0;
}

// A run of letters: a keyword or function, else an address letter and its number.
int GcodeSyntax::word(QStringView line, int i, std::vector<Span>& out) const {
    const int n = static_cast<int>(line.size());
    int end = i;
    while (end < n && isLetter(line[end])) {
        ++end;
    }
    QStringView letters = line.sliced(i, end - i);
    if (letters.size() > 1) {
        if (among(kKeywords, letters, upperOnly_)) {
            out.push_back({i, end - i, Kind::Keyword});
            return end;
        }
        if (among(kFunctions, letters, upperOnly_)) {
            out.push_back({i, end - i, Kind::Function});
            return end;
        }
        if (packedKeywords(letters, i, out)) {
            return end;
        }
    }
    // one address letter; the rest of the run is looked at again from the next letter
    const QChar letter = line[i].toUpper();
    int number = i + 1;
    while (number < n && line[number] == u' ') {
        ++number;
    }
    int numberEnd = skipNumber(line, number);
    if ((letter == u'G' || letter == u'M') && numberEnd > number) {
        out.push_back({i, numberEnd - i, Kind::Word});
        return numberEnd;
    }
    if ((letter == u'N' || letter == u'O') && numberEnd > number) {
        out.push_back({i, numberEnd - i, Kind::Label});
        return numberEnd;
    }
    out.push_back({i, 1, Kind::Address});
    return i + 1;
}

} // namespace m350::ui
