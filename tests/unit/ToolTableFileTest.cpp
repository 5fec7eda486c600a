// tool.tbl as LinuxCNC documents it: LinuxCNC-style files written here round-trip byte for byte, a
// bad line is reported with file:line:col and skipped while the rest loads, duplicates are refused
// naming the first line, edits keep the order and the comments, and the extras ride in the comment.
#include "core/tools/ToolTableFile.h"
#include "core/tools/ToolTableText.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace m350::tools {
namespace {

using testing::HasSubstr;

// As LinuxCNC's own writer and its users write them: signed fixed-point numbers, tabs, a header
// comment, blank lines, lower case, a comment glued to the last word.
constexpr const char* kLinuxCncTable =
    ";Tool table of the shop's router\n"
    "T1 P1 X+0.000000 Y+0.000000 Z+66.323000 D+6.000000 ;6 mm flat end mill\n"
    "T2\tP2\tZ+71.880000\tD+3.175000\t;1/8 inch ball\n"
    "\n"
    "; drills\n"
    "T10 P5 Z58.695 D5 I0 J0 Q0 ;5 mm drill\n"
    "t11 p6 z62;spot drill\n"
    "T12 P7 Z-0.125 ;\n";

ParsedToolTable parse(const std::string& text) { return parseToolTable(text, "tool.tbl"); }

TEST(ToolTableFile, ALinuxCncTableLoadsAndIsWrittenBackByteForByte) {
    ParsedToolTable parsed = parse(kLinuxCncTable);
    EXPECT_TRUE(parsed.issues.empty()) << formatIssue(parsed.issues.front());
    ASSERT_EQ(parsed.table.size(), 5u);
    const ToolEntry* t2 = parsed.table.find(2);
    ASSERT_NE(t2, nullptr);
    EXPECT_EQ(t2->pocket, 2);
    EXPECT_DOUBLE_EQ(t2->offset(kZ), 71.88);
    EXPECT_DOUBLE_EQ(*t2->diameter, 3.175);
    EXPECT_EQ(t2->comment, "1/8 inch ball");
    EXPECT_FALSE(t2->offsets[0]) << "T2 writes no X";
    const ToolEntry* t10 = parsed.table.find(10);
    ASSERT_NE(t10, nullptr);
    EXPECT_EQ(t10->pocket, 5);
    EXPECT_EQ(*t10->orientation, 0);
    const ToolEntry* t11 = parsed.table.find(11);
    ASSERT_NE(t11, nullptr) << "lower case and a comment right after the number";
    EXPECT_DOUBLE_EQ(t11->offset(kZ), 62.0);
    EXPECT_EQ(t11->comment, "spot drill");
    EXPECT_EQ(formatToolTable(parsed.table), kLinuxCncTable);
}

TEST(ToolTableFile, CrLfAndAMissingFinalNewlineSurviveTheRoundTrip) {
    const std::string text = "; dos\r\nT1 P1 Z1\r\nT2 P2 Z2";
    ParsedToolTable parsed = parse(text);
    ASSERT_EQ(parsed.table.size(), 2u);
    EXPECT_EQ(formatToolTable(parsed.table), text);
}

TEST(ToolTableFile, EachBadLineIsReportedWithItsColumnAndSkippedWhileTheRestLoads) {
    const std::string text = "T1 P1 Z10\n"
                             "T2 P2 Z0x10\n"          // 3: LinuxCNC reads it as 16
                             "T3 P3 Z5 S24000\n"      // 4: LinuxCNC skips the row
                             "T4 Z1\n"                // 5: no pocket
                             "T5 P5 Z1 Z2\n"          // 6: Z twice
                             "T6.5 P6\n"              // 7: not a whole number
                             "T7 P1001 Z1\n"          // 8: pocket beyond 1000
                             "T8 P8 Q10\n"            // 9: orientation beyond 9
                             "T9 P9 Znan\n"           // 10
                             "T10 P10 Z\n"            // 11: no number
                             "T0 P11\n"               // 12: T0 is the empty spindle
                             "T12 P12 Z-3.5 ;fine\n"; // 13
    ParsedToolTable parsed = parse("; header\n" + text);
    ASSERT_EQ(parsed.table.size(), 2u);
    EXPECT_NE(parsed.table.find(1), nullptr);
    EXPECT_NE(parsed.table.find(12), nullptr);
    std::vector<std::string> reported;
    for (const ToolTableIssue& issue : parsed.issues) {
        reported.push_back(formatIssue(issue));
    }
    EXPECT_THAT(reported, testing::ElementsAre(
                              HasSubstr("tool.tbl:3:7: error: 'Z0x10': Z needs a number"),
                              HasSubstr("tool.tbl:4:10: error: 'S' is no tool table word"),
                              HasSubstr("tool.tbl:5:1: error: a row needs T (the tool number) and P (its pocket): P is missing"),
                              HasSubstr("tool.tbl:6:10: error: Z is given twice (first at column 7)"),
                              HasSubstr("tool.tbl:7:1: error: 'T6.5': T needs a whole number"),
                              HasSubstr("tool.tbl:8:4: error: 'P1001': pockets run from 1 to 1000"),
                              HasSubstr("tool.tbl:9:7: error: 'Q10': the orientation Q runs from 0 to 9"),
                              HasSubstr("tool.tbl:10:7: error: 'Znan': Z needs a number"),
                              HasSubstr("tool.tbl:11:9: error: 'Z': Z needs a number right after the letter"),
                              HasSubstr("tool.tbl:12:1: error: 'T0': tool numbers start at 1")));
    for (const std::string& line : reported) {
        EXPECT_THAT(line, HasSubstr("(line skipped)"));
    }
    EXPECT_EQ(formatToolTable(parsed.table), "; header\n" + text) << "skipped lines are kept, not deleted";
}

TEST(ToolTableFile, DuplicateToolsAndPocketsAreRefusedNamingTheFirstLine) {
    ParsedToolTable parsed = parse("T1 P1 Z1\n"
                                   "T2 P2 Z2\n"
                                   "T1 P3 Z3 ;again\n"
                                   "T4 P2 Z4\n");
    ASSERT_EQ(parsed.issues.size(), 2u);
    EXPECT_EQ(formatIssue(parsed.issues[0]),
              "tool.tbl:3:1: error: tool 1 is already in the table (line 1): tool numbers must be unique (line skipped)");
    EXPECT_EQ(formatIssue(parsed.issues[1]),
              "tool.tbl:4:1: error: pocket 2 already holds a tool (line 2): pocket numbers must be unique (line skipped)");
    EXPECT_DOUBLE_EQ(parsed.table.find(1)->offset(kZ), 1.0) << "the first row of a tool counts";
    EXPECT_EQ(parsed.table.find(4), nullptr);
}

TEST(ToolTableFile, TheExtrasRideInTheCommentWhereLinuxCncKeepsThem) {
    ParsedToolTable parsed = parse("T1 P1 Z66.323 D6 ;6 mm end mill {rpm=24000 teeth=2 type=flat}\n"
                                   "T2 P2 Z70 ;engraver {teeth=1 type=engrave rpm=18000}\n"
                                   "T3 P3 Z60 ;a note {not ours}\n");
    ASSERT_TRUE(parsed.issues.empty());
    const ToolEntry* t1 = parsed.table.find(1);
    EXPECT_EQ(t1->comment, "6 mm end mill");
    EXPECT_DOUBLE_EQ(*t1->maxRpm, 24000.0);
    EXPECT_EQ(*t1->teeth, 2);
    EXPECT_EQ(*t1->type, ToolType::Flat);
    EXPECT_EQ(*parsed.table.find(2)->type, ToolType::Engrave);
    EXPECT_EQ(parsed.table.find(3)->comment, "a note {not ours}");
    EXPECT_FALSE(parsed.table.find(3)->hasExtras());
    ToolEntry edited = *parsed.table.find(2);
    edited.maxRpm = 20000.0;
    ASSERT_EQ(parsed.table.put(edited), std::nullopt);
    EXPECT_EQ(formatToolEntry(*parsed.table.find(2)), "T2 P2 Z70 ;engraver {rpm=20000 teeth=1 type=engrave}");
    ToolEntry bare;
    bare.tool = 9;
    bare.pocket = 9;
    bare.teeth = 4;
    EXPECT_EQ(formatToolEntry(bare), "T9 P9 ;{teeth=4}");
}

TEST(ToolTableFile, ABadExtraIsAWarningAndTheGroupStaysCommentText) {
    ParsedToolTable parsed = parse("T1 P1 Z1 ;x {rpm=fast teeth=2}\nT2 P2 Z2 ;{flutes=2}\nT3 P3 ;{type=saw}\n");
    ASSERT_EQ(parsed.table.size(), 3u) << "the rows load: only the extras are refused";
    ASSERT_EQ(parsed.issues.size(), 3u);
    EXPECT_THAT(formatIssue(parsed.issues[0]),
                HasSubstr("tool.tbl:1:14: warning: 'rpm=fast': rpm needs a positive number"));
    EXPECT_THAT(formatIssue(parsed.issues[1]), HasSubstr("tool.tbl:2:12: warning: 'flutes=2': the extras are rpm, teeth, type, hwear and dwear"));
    EXPECT_THAT(formatIssue(parsed.issues[2]), HasSubstr("'type=saw': the types are flat, ball"));
    EXPECT_EQ(parsed.table.find(1)->comment, "x {rpm=fast teeth=2}");
    EXPECT_FALSE(parsed.table.find(1)->teeth);
    EXPECT_FALSE(parsed.skippedLines());
}

TEST(ToolTableFile, EditsKeepTheOrderAndTheCommentsAndTouchOnlyTheirRow) {
    ParsedToolTable parsed = parse(kLinuxCncTable);
    ToolTable& table = parsed.table;
    ToolEntry t10 = *table.find(10);
    t10.offsets[kZ] = 58.5;
    ASSERT_EQ(table.put(t10), std::nullopt);
    ToolEntry added;
    added.tool = 20;
    added.pocket = 20;
    added.offsets[kZ] = 1e-7;
    added.comment = "new";
    ASSERT_EQ(table.put(added), std::nullopt);
    ASSERT_TRUE(table.remove(11));
    EXPECT_EQ(formatToolTable(table), ";Tool table of the shop's router\n"
                                      "T1 P1 X+0.000000 Y+0.000000 Z+66.323000 D+6.000000 ;6 mm flat end mill\n"
                                      "T2\tP2\tZ+71.880000\tD+3.175000\t;1/8 inch ball\n"
                                      "\n"
                                      "; drills\n"
                                      "T10 P5 Z58.5 D5 I0 J0 Q0 ;5 mm drill\n"
                                      "T12 P7 Z-0.125 ;\n"
                                      "T20 P20 Z1e-07 ;new\n");
    EXPECT_EQ(formatToolTable(parse(formatToolTable(table)).table), formatToolTable(table));
}

TEST(ToolTableFile, PutRefusesAPocketTakenAValueOutOfRangeAndChangesNothing) {
    ToolTable table = parse("T1 P1 Z1\nT2 P2 Z2\n").table;
    const ToolTable before = table;
    ToolEntry clash{};
    clash.tool = 3;
    clash.pocket = 2;
    EXPECT_THAT(table.put(clash).value_or(Message{}).english(), HasSubstr("pocket 2 already holds tool 2"));
    ToolEntry bad{};
    bad.tool = 1;
    bad.pocket = 1;
    bad.orientation = 12;
    EXPECT_THAT(table.put(bad).value_or(Message{}).english(), HasSubstr("orientation Q runs from 0 to 9"));
    bad.orientation.reset();
    bad.offsets[kZ] = std::numeric_limits<double>::infinity();
    EXPECT_THAT(table.put(bad).value_or(Message{}).english(), HasSubstr("the Z offset is not a finite number"));
    EXPECT_EQ(table, before);
    EXPECT_EQ(*table.freePocket(2), 3) << "pocket 2 is taken: the lowest free one";
}

TEST(ToolTableFile, AThousandToolsFitAndTheNextIsRefused) {
    std::string text;
    for (int tool = 1; tool <= 1001; ++tool) {
        text += "T" + std::to_string(tool) + " P" + std::to_string(tool == 1001 ? 0 : tool) + " Z1\n";
    }
    ParsedToolTable parsed = parse(text);
    EXPECT_EQ(parsed.table.size(), 1000u);
    ASSERT_EQ(parsed.issues.size(), 1u);
    EXPECT_EQ(formatIssue(parsed.issues[0]), "tool.tbl:1001:1: error: more than 1000 tools (line skipped)");
    ToolEntry extra{};
    extra.tool = 5000;
    extra.pocket = 0;
    EXPECT_THAT(parsed.table.put(extra).value_or(Message{}).english(), HasSubstr("full"));
}

TEST(ToolTableFile, NumbersReadAsTheSeedWritesThemAndNothingLooser) {
    EXPECT_EQ(parseTableNumber("+0.500000"), 0.5);
    EXPECT_EQ(parseTableNumber("-.25"), -0.25);
    EXPECT_EQ(parseTableNumber("3."), 3.0);
    EXPECT_EQ(parseTableNumber("1e-07"), 1e-7);
    for (const char* bad : {"", "+", ".", "0x10", "nan", "inf", "1.2.3", "1e", "--1", "1,5"}) {
        EXPECT_FALSE(parseTableNumber(bad)) << bad;
    }
    EXPECT_EQ(parseWholeNumber("3.0"), 3);
    EXPECT_FALSE(parseWholeNumber("3.5"));
}

} // namespace
} // namespace m350::tools
