// A large main program has its second half read on a second thread (PlainLinePrefetch) while the
// parser reads the first, and the parser adopts what it read. These tests lower the size that
// takes that path to nothing and compare every block, unit, label and diagnostic with the same
// program read on one thread, with the middle of the text falling on every kind of line.
#include "RandomProgramLines.h"
#include "SameBlock.h"

#include "core/gcode/BlockList.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>
#include <vector>

namespace m350 {
namespace {

using gcode::Block;
using gcode::Program;

struct Parsed {
    Program program;
    std::vector<std::string> diagnostics;
};

Parsed parse(const std::string& text, bool secondThread) {
    Parsed parsed;
    gcode::Parser parser(gcode::Dialect::m350());
    parser.setSecondThreadFrom(secondThread ? 0 : std::numeric_limits<std::size_t>::max());
    parser.addFile(parsed.program, "p.nc", text, gcode::FileRole::Main);
    parser.finish(parsed.program);
    for (const gcode::Diagnostic& d : parser.diagnostics()) {
        parsed.diagnostics.push_back(gcode::formatDiagnostic(d));
    }
    return parsed;
}

// Whether the program read on two threads is the one read on one; and whether the second thread
// gave any blocks (the parser adopted its storage).
bool expectSameProgram(const std::string& text) {
    const Parsed one = parse(text, false);
    const Parsed two = parse(text, true);
    EXPECT_EQ(one.diagnostics, two.diagnostics);
    EXPECT_TRUE(one.program.adoptedStorage.empty());
    EXPECT_EQ(one.program.blocks.size(), two.program.blocks.size());
    for (std::size_t i = 0; i < one.program.blocks.size() && i < two.program.blocks.size(); ++i) {
        expectSameBlock(one.program.blocks[i], two.program.blocks[i], i);
        if (::testing::Test::HasFailure()) {
            break;
        }
    }
    EXPECT_EQ(one.program.units.size(), two.program.units.size());
    for (std::size_t u = 0; u < one.program.units.size() && u < two.program.units.size(); ++u) {
        EXPECT_EQ(one.program.units[u].number, two.program.units[u].number);
        EXPECT_EQ(one.program.units[u].begin, two.program.units[u].begin);
        EXPECT_EQ(one.program.units[u].end, two.program.units[u].end);
    }
    // Every label is found where the program read on one thread has it.
    for (std::size_t i = 0; i < one.program.blocks.size(); ++i) {
        const Block& block = one.program.blocks[i];
        if (block.label >= 0) {
            const auto unit = one.program.unitOfBlock(static_cast<std::uint32_t>(i));
            EXPECT_EQ(one.program.findLabel(unit, block.label, 0), two.program.findLabel(unit, block.label, 0))
                << "N" << block.label;
        }
    }
    return !two.program.adoptedStorage.empty();
}

// Every kind of line, at random (RandomProgramLines.h), and besides GOTOs to a label of the second
// half, calls of a subprogram (and of a missing one) and now and then a syntax error. The middle
// of the text falls on any of them.
std::string randomProgram(std::mt19937& random, int lines) {
    std::uniform_int_distribution<int> kind(0, 99);
    std::uniform_int_distribution<int> special(0, 99);
    std::string text = "#1 = 0\n";
    int loopsLeft = 20;
    const std::string farLabel = std::to_string(lines - lines % 7);
    for (int i = 0; i < lines; ++i) {
        int k = kind(random);
        if (k >= 74 && k < 86 && random() % 20 != 0) {
            k = 90; // lines the second thread stops at, rarer: it reads long runs, as in CAM output
        }
        const char* end = k % 17 == 0 ? "\r" : k % 13 == 0 ? "\r\n" : "\n";
        switch (special(random)) {
        case 0: text += "IF [#1 GT 5] GOTO" + farLabel + end; break;
        case 1: text += std::string(random() % 4 == 0 ? "M98 P3000" : "M98 P2000") + end; break; // no O3000
        case 2: text += std::string(random() % 8 == 0 ? "G1 X1..5" : "G0 Z5") + end; break;
        default: appendRandomLine(text, k, i, end, loopsLeft); break;
        }
    }
    text += "N" + farLabel + " G0 Z10\n";
    text += "M30\n";
    text += "O2000\nG1 X1 Y1\nM99\n";
    return text;
}

TEST(PlainLinePrefetch, RandomProgramsAreTheSameReadOnTwoThreads) {
    std::mt19937 random(20261124);
    int adopted = 0;
    for (int round = 0; round < 24; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        adopted += expectSameProgram(randomProgram(random, 2000 + static_cast<int>(random() % 3000))) ? 1 : 0;
        if (::testing::Test::HasFailure()) {
            break;
        }
    }
    // Most middles fall where plain lines follow: the second thread's blocks were taken.
    EXPECT_GE(adopted, 12);
}

TEST(PlainLinePrefetch, ACamProgramIsReadMostlyByTheSecondThread) {
    std::string text = "O1234 (a CAM program)\nG90 G54 G17\nT1 M6\nM3 S12000\n";
    for (int i = 0; i < 20000; ++i) {
        text += (i % 50 == 0 ? "N" + std::to_string(i + 10) + " " : std::string()) + g1Line(i) + "\n";
    }
    text += "M5\nM30\n";
    EXPECT_TRUE(expectSameProgram(text));
    const Parsed two = parse(text, true);
    EXPECT_TRUE(two.diagnostics.empty());
    EXPECT_EQ(two.program.blocks.size(), 20000u + 6u);
    EXPECT_EQ(two.program.blocks[two.program.blocks.size() - 1].location.line, 20000u + 6u);
}

// The middle of the text is inside a `/* */` comment: what the second thread read as code is
// commented out, so the parser reads those lines itself.
TEST(PlainLinePrefetch, AMiddleInsideACommentIsReadByTheParser) {
    std::string text;
    for (int i = 0; i < 1000; ++i) {
        text += g1Line(i) + "\n";
    }
    text += "G1 X1 /* a comment that runs over the middle\n";
    for (int i = 0; i < 3000; ++i) {
        text += g1Line(i) + "\n"; // commented out
    }
    text += "*/ G1 X5 Y5\n";
    for (int i = 0; i < 1000; ++i) {
        text += g1Line(i) + "\n";
    }
    text += "M30\n";
    EXPECT_FALSE(expectSameProgram(text));
    const Parsed two = parse(text, true);
    EXPECT_EQ(two.program.blocks.size(), 1000u + 1u + 1u + 1000u + 1u);
}

// Nothing but blank lines and comments before the middle: no block, no unit yet, so the parser
// reads on by itself.
TEST(PlainLinePrefetch, NoBlockBeforeTheMiddleMeansOneThread) {
    std::string text(100000, '\n');
    for (int i = 0; i < 1000; ++i) {
        text += g1Line(i) + "\n";
    }
    EXPECT_FALSE(expectSameProgram(text));
}

// An error in the second half is reported as on one thread, at its line and column.
TEST(PlainLinePrefetch, AnErrorInTheSecondHalfIsReportedAtItsLine) {
    std::string text;
    for (int i = 0; i < 4000; ++i) {
        text += (i == 3500 ? std::string("G1 X1..5") : g1Line(i)) + "\n";
    }
    text += "M30\n";
    EXPECT_TRUE(expectSameProgram(text));
    const Parsed two = parse(text, true);
    ASSERT_EQ(two.diagnostics.size(), 1u);
    EXPECT_NE(two.diagnostics.front().find("p.nc:3501:"), std::string::npos) << two.diagnostics.front();
}

} // namespace
} // namespace m350
