// Issue 13: a 1 GB program must run in bounded memory. Above a size, the main program's chunks of
// plain lines are dropped once parsed and parsed again from the mapped file when they run. These
// tests lower that size to a few bytes, so small programs take the same path, and compare every
// block and every run with the program kept whole.
#include "RandomProgramLines.h"
#include "RunProgram.h"
#include "SameBlock.h"

#include "core/gcode/BlockList.h"
#include "core/gcode/Dialect.h"
#include "core/gcode/Parser.h"
#include "core/gcode/Program.h"
#include "core/gcode/SourceText.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace m350 {
namespace {

using gcode::Block;
using gcode::BlockList;
using gcode::Program;

constexpr std::uint32_t kChunk = BlockList::kChunkSize;

// Every kind of line a dropped chunk must read again as it was, around the chunk boundaries:
// comments, blank lines, labels, block delete, CR and CRLF line ends, a `/* */` comment across a
// boundary, and lines that must stay (a loop, assignments, a call).
std::string mixedProgram() {
    std::string text;
    int line = 0;
    auto add = [&](const std::string& s, const char* end = "\n") {
        text += s;
        text += end;
        ++line;
    };
    add("#1 = 0");
    for (int i = 0; i < 3 * static_cast<int>(kChunk) + 100; ++i) {
        if (i % 1000 == 7) {
            add("");
        } else if (i % 997 == 3) {
            add("N" + std::to_string(10 + i) + " " + g1Line(i) + " (labelled)");
        } else if (i % 501 == 5) {
            add("/" + g1Line(i));
        } else if (i >= 5000 && i < 5200) {
            add(g1Line(i), "\r"); // an old Mac export pasted in
        } else if (i >= 5200 && i < 5300) {
            add(g1Line(i), "\r\n");
        } else if (i == 2 * static_cast<int>(kChunk) - 2) {
            add(g1Line(i) + " /* a comment that runs");
            add("G0 X999 over a chunk boundary");
            add("*/ G1 X5");
        } else {
            add(g1Line(i));
        }
    }
    add("WHILE [#1 LT 2] DO1");
    add("#1 = #1 + 1");
    add("END1");
    for (int i = 0; i < static_cast<int>(kChunk) + 10; ++i) {
        add(g1Line(i) + " (after the loop)");
    }
    add("M98 P2000");
    add("M30");
    add("O2000");
    add("G1 X1 Y1");
    add("M99");
    return text;
}

std::string writeFile(const std::string& text) { return test::writeTempFile(text); }

Program parseWhole(const std::string& text) {
    Program program;
    gcode::Parser parser(gcode::Dialect::m350());
    parser.addFile(program, "p.nc", text, gcode::FileRole::Main);
    parser.finish(program);
    EXPECT_TRUE(parser.diagnostics().empty()) << gcode::formatDiagnostic(parser.diagnostics().front());
    return program;
}

Program parseInPart(const std::string& path) {
    Program program;
    auto source = gcode::readSourceFile(path);
    EXPECT_TRUE(std::holds_alternative<gcode::SourceText>(source));
    gcode::Parser parser(gcode::Dialect::m350());
    parser.setDropChunksAbove(0);
    parser.addSource(program, std::get<gcode::SourceText>(source), gcode::FileRole::Main);
    parser.finish(program);
    EXPECT_TRUE(parser.diagnostics().empty()) << gcode::formatDiagnostic(parser.diagnostics().front());
    return program;
}

TEST(ProgramKeptInPart, DroppedChunksReadAgainAsTheyWereParsed) {
    const std::string text = mixedProgram();
    const std::string path = writeFile(text);
    const Program whole = parseWhole(text);
    const Program inPart = parseInPart(path);
    ASSERT_EQ(whole.blocks.size(), inPart.blocks.size());
    const std::size_t chunks = (inPart.blocks.size() + kChunk - 1) / kChunk;
    // Chunk 0 holds `#1 = 0` and chunk 1 ends inside the comment, so chunk 2 starts in it; the
    // chunk of the loop and the last one (shared with nothing else here) stay too.
    EXPECT_GE(inPart.blocks.droppedChunks(), 1u);
    EXPECT_LE(inPart.blocks.droppedChunks(), chunks - 3);
    for (std::size_t i = 0; i < whole.blocks.size(); ++i) {
        expectSameBlock(whole.blocks[i], inPart.blocks[i], i);
    }
    // Backwards, a chunk at a time: every look-up past the cache's few chunks parses one again.
    for (std::size_t i = whole.blocks.size(); i-- > 0;) {
        const Block& kept = inPart.blocks[i];
        ASSERT_EQ(kept.location.line, whole.blocks[i].location.line) << i;
    }
    EXPECT_EQ(inPart.units.size(), whole.units.size());
    std::remove(path.c_str());
}

// Random programs of every kind of line, each kind at random places, so chunk boundaries fall
// everywhere: inside `/* */` comments, between CR and LF, on labels, on macro lines. Macro lines
// are rare (a chunk with one stays whole), as in CAM output with a few macro statements.
std::string randomProgram(std::mt19937& random) {
    std::uniform_int_distribution<int> kind(0, 99);
    std::uniform_int_distribution<int> rare(0, 9999);
    std::string text;
    int loopsLeft = 40;
    const int lines = 20000 + static_cast<int>(random() % 4000);
    for (int i = 0; i < lines; ++i) {
        int k = kind(random);
        if (k >= 77 && k < 86) {
            k = 90; // macro lines only from `rare`
        }
        if (rare(random) == 0) {
            k = 77 + static_cast<int>(random() % 3) * 3; // an assignment, a loop or an expression
        }
        const char* end = k % 17 == 0 ? "\r" : k % 13 == 0 ? "\r\n" : "\n";
        appendRandomLine(text, k, i, end, loopsLeft);
    }
    text += "M30\n";
    return text;
}

TEST(ProgramKeptInPart, RandomProgramsReadAgainAsTheyWereParsed) {
    std::mt19937 random(20261124);
    for (int round = 0; round < 4; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const std::string text = randomProgram(random);
        const std::string path = writeFile(text);
        const Program whole = parseWhole(text);
        const Program inPart = parseInPart(path);
        ASSERT_EQ(whole.blocks.size(), inPart.blocks.size());
        EXPECT_GE(inPart.blocks.droppedChunks(), 1u);
        std::uniform_int_distribution<std::size_t> anyBlock(0, whole.blocks.size() - 1);
        for (int n = 0; n < 4000; ++n) { // random order: chunks leave and come back to the cache
            const std::size_t i = anyBlock(random);
            expectSameBlock(whole.blocks[i], inPart.blocks[i], i);
            if (::testing::Test::HasFailure()) {
                break;
            }
        }
        std::remove(path.c_str());
    }
}

// The first block of chunk 1 is on the line that closes a `/* */` comment: parsed again alone, that
// line would read `*/` as code, so the chunk must stay.
TEST(ProgramKeptInPart, AChunkThatStartsInsideACommentStays) {
    std::string text;
    for (int i = 0; i + 1 < static_cast<int>(kChunk); ++i) {
        text += g1Line(i) + "\n";
    }
    text += "G1 X1 /* the last block of chunk 0 opens a comment\n";
    text += "G0 X999 (inside it: no block)\n";
    text += "*/ G1 X5 Y5\n"; // the first block of chunk 1
    for (int i = 0; i < static_cast<int>(kChunk); ++i) {
        text += g1Line(i) + "\n";
    }
    text += "M30\n";
    const std::string path = writeFile(text);
    const Program whole = parseWhole(text);
    const Program inPart = parseInPart(path);
    ASSERT_EQ(whole.blocks.size(), inPart.blocks.size());
    EXPECT_EQ(inPart.blocks.droppedChunks(), 1u); // chunk 0 only; chunk 2 is not full
    for (std::size_t i = kChunk - 2; i < 2 * kChunk + 1; ++i) {
        expectSameBlock(whole.blocks[i], inPart.blocks[i], i);
    }
    EXPECT_EQ(inPart.blocks[kChunk].words[1].number, 5.0);
    std::remove(path.c_str());
}

TEST(ProgramKeptInPart, ASmallProgramIsKeptWholeUnlessAsked) {
    const std::string path = writeFile(mixedProgram());
    Program program;
    auto source = gcode::readSourceFile(path);
    gcode::Parser parser(gcode::Dialect::m350());
    parser.addSource(program, std::get<gcode::SourceText>(source), gcode::FileRole::Main);
    EXPECT_EQ(program.blocks.droppedChunks(), 0u);
    std::remove(path.c_str());
}

// A loop and a subprogram jump back and forth over dropped chunks: each pass parses them again.
std::string loopingProgram() {
    std::string text = "#1 = 0\nN100\n";
    for (int i = 0; i < 6 * static_cast<int>(kChunk); ++i) { // more chunks than the cache holds
        text += g1Line(i) + "\n";
    }
    text += "#1 = #1 + 1\nM98 P2000\nIF [#1 LT 3] GOTO100\nM30\nO2000\n";
    for (int i = 0; i < 2 * static_cast<int>(kChunk); ++i) {
        text += "G1 Z-" + std::to_string(i % 13) + " Y" + std::to_string(i % 17) + "\n";
    }
    text += "#101 = #101 + 1\nM99\n";
    return text;
}

TEST(ProgramKeptInPart, ARunIsTheSameAsWithTheProgramKeptWhole) {
    controller::RunSettings whole;
    whole.maxSimTime = 1e9;
    controller::RunSettings inPart = whole;
    inPart.programKeptWholeUpTo = 0;
    auto a = test::runProgram(test::m350Machine(), loopingProgram(), whole);
    auto b = test::runProgram(test::m350Machine(), loopingProgram(), inPart);
    EXPECT_RUN_OK(a);
    EXPECT_RUN_OK(b);
    EXPECT_EQ(a.report.blocks, b.report.blocks);
    EXPECT_EQ(a.report.simTime, b.report.simTime);
    EXPECT_EQ(a.report.machine, b.report.machine);
    EXPECT_EQ(b.number(1), 3.0);
    EXPECT_EQ(b.number(101), 3.0);
}

// Start at a line (断点 / the panel's start at line): found by a binary search over the blocks,
// most of which are on disk; the run from there is the same as with the program kept whole.
TEST(ProgramKeptInPart, StartingAtALineIsTheSameAsWithTheProgramKeptWhole) {
    const std::string text = loopingProgram();
    controller::RunSettings whole;
    whole.maxSimTime = 1e9;
    controller::RunSettings inPart = whole;
    inPart.programKeptWholeUpTo = 0;
    std::vector<controller::RunReport> reports;
    for (const controller::RunSettings& settings : {whole, inPart}) {
        const std::string path = test::writeTempFile(text);
        controller::Controller c(test::m350Machine(), settings);
        ASSERT_TRUE(c.loadFile(path));
        Message why;
        EXPECT_FALSE(c.breakRun().startAtLine(40000, &why));
        EXPECT_NE(why.english().find("its blocks are on lines 1-"), std::string::npos) << why;
        ASSERT_TRUE(c.breakRun().startAtLine(15000, &why)) << why; // in the fourth chunk
        EXPECT_EQ(c.advance(1e9), controller::Controller::RunState::Finished);
        reports.push_back(c.status().report());
        std::remove(path.c_str());
    }
    EXPECT_EQ(reports[0].blocks, reports[1].blocks);
    EXPECT_EQ(reports[0].simTime, reports[1].simTime);
    EXPECT_TRUE(reports[0].machine == reports[1].machine);
    EXPECT_GT(reports[1].blocks, 3 * 6 * kChunk); // started mid-loop, then looped back to N100
}

TEST(ProgramKeptInPart, AFileChangedWhileItRunsStopsTheRunAndSaysSo) {
    controller::RunSettings settings;
    settings.programKeptWholeUpTo = 0;
    const std::string path = test::writeTempFile(loopingProgram());
    controller::Controller controller(test::m350Machine(), settings);
    ASSERT_TRUE(controller.loadFile(path));
    {
        // An editor saves another program over it (the file is mapped: the run sees the new text).
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << "\n\n" << loopingProgram();
    }
    const controller::RunReport report = controller.run();
    ASSERT_TRUE(report.alarm);
    EXPECT_EQ(report.alarm->code, AlarmCode::SuspectLine);
    EXPECT_NE(report.alarm->message.find("changed on disk while its program ran"), std::string::npos)
        << report.alarm->message;
    std::remove(path.c_str());
}

} // namespace
} // namespace m350
