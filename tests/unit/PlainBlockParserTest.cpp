// The plain-word fast path must give exactly what the general parser gives, for every line it
// accepts, and must leave every other line to the general parser.
#include "core/gcode/BlockParser.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/PlainBlockParser.h"

#include "ParseSupport.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace {

using namespace m350::gcode;

struct Parsed {
    std::optional<Block> block;
    BlockStorage storage;
    std::vector<Diagnostic> diagnostics;
};

void parseWith(bool plainPath, const Dialect& dialect, const std::string& line, Parsed& out) {
    BlockParser parser(dialect, out.storage, out.diagnostics, "t.nc", 0);
    parser.setPlainPath(plainPath);
    out.block = parser.parse(line, 7);
}

void expectSameBlock(const Block& a, const BlockStorage& aStorage, const Block& b, const BlockStorage& bStorage,
                     const std::string& line) {
    EXPECT_EQ(a.location.line, b.location.line) << line;
    EXPECT_EQ(a.location.column, b.location.column) << line;
    EXPECT_EQ(a.label, b.label) << line;
    EXPECT_EQ(a.programNumber, b.programNumber) << line;
    EXPECT_EQ(a.blockDelete, b.blockDelete) << line;
    EXPECT_EQ(a.programEnd, b.programEnd) << line;
    EXPECT_EQ(a.control, b.control) << line;
    EXPECT_EQ(a.comment, b.comment) << line;
    EXPECT_EQ(a.assignments.size(), b.assignments.size()) << line;
    ASSERT_EQ(a.words.size(), b.words.size()) << line;
    for (std::size_t i = 0; i < a.words.size(); ++i) {
        EXPECT_EQ(a.words[i].letter, b.words[i].letter) << line;
        EXPECT_EQ(a.words[i].column, b.words[i].column) << line;
        ASSERT_EQ(a.words[i].isNumber(), b.words[i].isNumber()) << line;
        if (a.words[i].isNumber()) {
            EXPECT_EQ(a.words[i].number, b.words[i].number) << line; // bit-identical conversion
        } else {
            EXPECT_EQ(aStorage.expressions[a.words[i].value].kind, bStorage.expressions[b.words[i].value].kind)
                << line;
        }
    }
}

void expectSameResult(const Dialect& dialect, const std::string& line) {
    Parsed fast;
    Parsed general;
    parseWith(true, dialect, line, fast);
    parseWith(false, dialect, line, general);
    ASSERT_EQ(fast.block.has_value(), general.block.has_value()) << line;
    EXPECT_EQ(fast.diagnostics.size(), general.diagnostics.size()) << line;
    if (fast.block) {
        expectSameBlock(*fast.block, fast.storage, *general.block, general.storage, line);
    }
}

// Read in place from a text that goes on after the line's end, the line gives what it gives alone
// and ends where it ends, whatever follows.
void expectSameInPlace(const Dialect& dialect, const std::string& line, const std::string& lineEnd) {
    const std::string text = line + lineEnd + "G1 X9 (the next line)";
    BlockStorage inPlaceStorage;
    Block inPlace;
    std::size_t length = 0;
    const PlainResult result = parsePlainLine(text.data(), dialect, {0, 7, 0}, inPlaceStorage, inPlace, length);
    BlockStorage aloneStorage;
    Block alone;
    ASSERT_EQ(result, parsePlainBlock(line, dialect, {0, 7, 0}, aloneStorage, alone)) << line;
    if (result == PlainResult::Declined) {
        return;
    }
    EXPECT_EQ(length, line.size()) << line;
    if (result == PlainResult::Parsed) {
        expectSameBlock(inPlace, inPlaceStorage, alone, aloneStorage, line);
    }
}

TEST(PlainBlockParser, AcceptsPlainWordLines) {
    BlockStorage storage;
    Block block;
    EXPECT_EQ(parsePlainBlock("N10 G1 X12.5 Y-3 F1000 (rough)", Dialect::m350(), {0, 1, 0}, storage, block),
              PlainResult::Parsed);
    EXPECT_EQ(block.label, 10);
    EXPECT_EQ(block.words.size(), 4u);
    EXPECT_EQ(block.comment, "rough");
    EXPECT_EQ(block.words[2].number, -3.0);
    EXPECT_EQ(storage.expressions.size(), 0u); // plain numbers live in their words
    EXPECT_EQ(parsePlainBlock("   (only a comment)", Dialect::m350(), {0, 1, 0}, storage, block),
              PlainResult::Empty);
}

TEST(PlainBlockParser, DeclinesEverythingElse) {
    for (const char* line : {"#1=2", "G1 X#1", "IF [#1 EQ 1] GOTO5", "O100", "/G1 X1", "G1 X[1+2]", "G1 X1.2.3",
                             "X1-2", "GOTO5", "N1.5 G1", "N-1 G1", "G1 N5", "%", "G1 X（1）", "(换刀) G1 X1",
                             "X", "X-", "X- 1", "G1 X1 (unclosed", "WHILE [1] DO1", "G1 X99999999999999999999"}) {
        BlockStorage storage;
        Block block;
        EXPECT_EQ(parsePlainBlock(line, Dialect::m350(), {0, 1, 0}, storage, block), PlainResult::Declined)
            << line;
        EXPECT_TRUE(block.words.empty()) << line;
    }
}

TEST(PlainBlockParser, SameResultAsTheGeneralParserOnHandPickedLines) {
    for (const char* line : {"G1 X12.5 Y-3 F1000", "  g1 x.5 y+2. z-0.001", "N50", "N50 (label) G0 Z0", "M30",
                             "M02", "G04 P200 ;done", "G04 P200 // done", "T2 M6 (换刀)", "G1X1Y2Z3", "N0010 M5",
                             "X1234567.890123", "X0.1234567890123456789", "F1.", "", "   ", "(a)(b)X1", "S12000 M3\r"}) {
        expectSameResult(Dialect::m350(), line);
        expectSameResult(Dialect::fanuc(), line);
        if (std::string_view(line).find('\r') == std::string_view::npos) {
            expectSameInPlace(Dialect::m350(), line, "\n");
            expectSameInPlace(Dialect::fanuc(), line, "\r\n");
        }
    }
}

TEST(PlainBlockParser, SameResultAsTheGeneralParserOnRandomLines) {
    const std::vector<std::string> pieces = {"G", "X", "Y", "z", "N", "M", "F", "1", "0.5", ".25", "-", "+", " ",
                                             "12", "3.", "(c)", ";", "//", "(", ")", "#", "[", "]", "O", "/", "\t",
                                             "30", "99999999999999999", "1.2.3", "A", "B", "GOTO", "EQ"};
    std::mt19937 rng(350);
    std::uniform_int_distribution<std::size_t> pick(0, pieces.size() - 1);
    std::uniform_int_distribution<int> length(0, 12);
    for (int n = 0; n < 20000; ++n) {
        std::string line;
        for (int k = length(rng); k > 0; --k) {
            line += pieces[pick(rng)];
        }
        expectSameResult(n % 2 ? Dialect::m350() : Dialect::fanuc(), line);
        expectSameInPlace(n % 2 ? Dialect::m350() : Dialect::fanuc(), line, n % 3 ? "\n" : "\r");
        if (HasFailure()) {
            return;
        }
    }
}

TEST(PlainBlockParser, ALineEndInsideACallersLineIsLeftToTheGeneralParser) {
    BlockStorage storage;
    Block block;
    EXPECT_EQ(parsePlainBlock("G1 X1\rY2", Dialect::m350(), {0, 1, 0}, storage, block), PlainResult::Declined);
    expectSameResult(Dialect::m350(), "G1 X1\rY2");
    expectSameResult(Dialect::m350(), "G1 X1\nY2");
}

TEST(PlainBlockParser, InPlaceAnUnclosedCommentOrATrailingCommentStopsAtTheLineEnd) {
    const std::string unclosed = "G1 X1 (open\nG1 X2 (closed)\n";
    BlockStorage storage;
    Block block;
    std::size_t length = 0;
    EXPECT_EQ(parsePlainLine(unclosed.data(), Dialect::m350(), {0, 1, 0}, storage, block, length),
              PlainResult::Declined);
    const std::string trailing = "G1 X1 ; rest\nG1 X2\n";
    ASSERT_EQ(parsePlainLine(trailing.data(), Dialect::m350(), {0, 1, 0}, storage, block, length),
              PlainResult::Parsed);
    EXPECT_EQ(length, 12u);
    EXPECT_EQ(block.words.size(), 2u);
}

// A whole program through the Parser (which reads plain lines in place before it looks for their
// end) gives, line by line, what the general parser gives each line alone: same line numbers,
// same blocks, whatever the line ends.
TEST(PlainBlockParser, AProgramReadInPlaceGivesWhatEachLineGivesAlone) {
    const std::vector<std::string> lines = {"G1 X1.5 Y-2", "", "  ", "N10 G0 Z5", "(comment)", "G1 X2 ; rest",
                                            "#1=2", "G1 X#1", "M3 S1000 (spindle)", "F1.", "X.5", "G1 X1 (open",
                                            "N20", "%", "G1 X1.2.3", "T2 M6"};
    const std::vector<std::string> ends = {"\n", "\r\n", "\r"};
    std::mt19937 rng(13);
    for (int n = 0; n < 300; ++n) {
        // One kind of line end a program: an empty line after a CR line would make a CRLF.
        const std::string& end = ends[rng() % ends.size()];
        std::vector<std::string> chosen;
        std::string text;
        const int count = 1 + static_cast<int>(rng() % 12);
        for (int k = 0; k < count; ++k) {
            chosen.push_back(lines[rng() % lines.size()]);
            text += chosen.back();
            if (k + 1 < count || rng() % 2 == 0) {
                text += end;
            }
        }
        support::Parsed whole = support::parse(text, Dialect::m350());
        BlockStorage storage;
        std::vector<Diagnostic> diagnostics;
        BlockParser alone(Dialect::m350(), storage, diagnostics, "test.nc", 0);
        alone.setPlainPath(false);
        std::size_t next = 0;
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            const std::optional<Block> block = alone.parse(chosen[k], static_cast<std::uint32_t>(k + 1));
            if (!block) {
                continue;
            }
            ASSERT_LT(next, whole.program.blocks.size()) << text;
            expectSameBlock(whole.program.blocks[next], whole.program, *block, storage, chosen[k]);
            ++next;
        }
        EXPECT_EQ(next, whole.program.blocks.size()) << text;
        if (HasFailure()) {
            return;
        }
    }
}

} // namespace
