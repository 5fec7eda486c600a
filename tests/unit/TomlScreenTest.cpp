// The screen in front of toml++ (core/files/TomlScreen.h): what it refuses and where, what it lets
// through, and a sweep showing that what it lets through toml++ reads without undefined behaviour
// (the sweep fails only in the ASan/UBSan build of scripts/test.sh, where UBSan stops at it).
#define TOML_HEADER_ONLY 1
#include "core/files/Toml.h"
#include "core/files/TomlScreen.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace m350::config {
namespace {

std::string utf8(char32_t c) {
    std::string s;
    if (c < 0x80) {
        s += static_cast<char>(c);
    } else if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        s += static_cast<char>(0xE0 | (c >> 12));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        s += static_cast<char>(0xF0 | (c >> 18));
        s += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    }
    return s;
}

std::string refusal(std::string_view text) {
    auto refused = files::findCharacterTomlCannotRead(text);
    return refused ? std::to_string(refused->line) + ":" + std::to_string(refused->column) + ": " + refused->message
                   : "accepted";
}

TEST(TomlScreenTest, ANonAsciiCharacterOutsideAStringOrCommentIsRefusedAtItsPlace) {
    EXPECT_EQ(refusal("[params]\n61 = 3000 \xE3\x80\x82\n"),
              "2:11: character '\xE3\x80\x82' (U+3002) may only stand inside a string or a comment");
    EXPECT_EQ(refusal("a = 1\n \xC2\xB0 = 2\n"), "2:2: character '\xC2\xB0' (U+00B0) may only stand inside a string "
                                                  "or a comment");
    EXPECT_EQ(refusal("\xE5\x88\x80 = 1\n"), "1:1: character '\xE5\x88\x80' (U+5200) may only stand inside a string "
                                              "or a comment");
    EXPECT_EQ(refusal("a = [1,\n  \xF0\x9F\x94\xA7]\n"),
              "2:3: character '\xF0\x9F\x94\xA7' (U+1F527) may only stand inside a string or a comment");
}

TEST(TomlScreenTest, AFullWidthSpaceOrAStrayByteOrderMarkSaysWhatItIs) {
    EXPECT_EQ(refusal("a =\xE3\x80\x80" "1\n"),
              "1:4: character '\xE3\x80\x80' (U+3000) may only stand inside a string or a comment: a full-width "
              "space; type an ASCII space instead");
    EXPECT_EQ(refusal("a = 1\n\xEF\xBB\xBF" "b = 2\n"),
              "2:1: character '\xEF\xBB\xBF' (U+FEFF) may only stand inside a string or a comment: a byte-order "
              "mark belongs only at the very start of the file");
    EXPECT_EQ(refusal("\xEF\xBB\xBF" "a = 1\n"), "accepted");
}

TEST(TomlScreenTest, BytesThatAreNotUtf8AreRefusedOutsideStrings) {
    EXPECT_EQ(refusal("a = 1 \xFF\n"), "1:7: byte 0xFF, which is not UTF-8, may only stand inside a string or a comment");
    EXPECT_EQ(refusal("a = 1 \xE3\x80\n"),
              "1:7: byte 0xE3, which is not UTF-8, may only stand inside a string or a comment");
}

TEST(TomlScreenTest, StringsAndCommentsMayHoldAnyCharacter) {
    EXPECT_EQ(refusal("# \xE4\xB8\xBB\xE8\xBD\xB4\xE3\x80\x82 \xC2\xB1" "5\xC2\xB0\n"
                      "name = \"\xE5\x88\x80\xE5\xBA\x93\xE3\x80\x8C\xE6\x96\x97\xE7\xAC\xA0\xE3\x80\x8D\" # \xEF\xB9\x90\n"
                      "'\xC3\xA9' = '\xE3\x80\x82'\n"
                      "\"key \\\" \xC2\xB0\" = \"\\\\\xE3\x80\x82\"\n"
                      "text = \"\"\"\n\xE3\x80\x82 \xC2\xB0 \"\" \xEF\xB9\x90\"\"\"\"\n"
                      "raw = '''\xE3\x80\x82\n\\ \xC2\xB0'''''  # \xE3\x80\x82\n"),
              "accepted");
}

TEST(TomlScreenTest, AQuoteInsideABareValueOpensNoString) {
    // toml++ reads `5"é"` as one bare value and tests each of its characters for whitespace.
    EXPECT_EQ(refusal("a = 5\"\xC3\xA9\"\n"), "1:7: character '\xC3\xA9' (U+00E9) may only stand inside a string or "
                                              "a comment");
    EXPECT_EQ(refusal("a = 1.\"\xC3\xA9\"\n"), "1:8: character '\xC3\xA9' (U+00E9) may only stand inside a string "
                                               "or a comment");
    EXPECT_EQ(refusal("a = =\"\xC3\xA9\"\n"), "1:7: character '\xC3\xA9' (U+00E9) may only stand inside a string or "
                                              "a comment");
    EXPECT_EQ(refusal("a = [1, x[\"\xC3\xA9\"]]\n"), "1:12: character '\xC3\xA9' (U+00E9) may only stand inside a "
                                                      "string or a comment");
}

TEST(TomlScreenTest, QuotedKeysTableNamesAndValuesInArraysAndInlineTablesAreStrings) {
    EXPECT_EQ(refusal("a.\"\xC3\xA9\" = 1\n"
                      "[b.\"\xE5\x88\x80\"]\n"
                      "[[c.'\xE5\x88\x80']]\n"
                      "x = { \"\xC3\xA9\" = 1, y.\"\xC2\xB0\" = [\"\xC3\xA9\", '\xE3\x80\x82', [\"\xC2\xB0\"]] }\n"
                      "z = [\n  \"\xE3\x80\x82\", # \xE3\x80\x82\n  {k = \"\xC2\xB0\"},\n  '''\xC2\xB0'''\n]\n"
                      "w = \"x\" # \xC2\xB0\n"),
              "accepted");
}

TEST(TomlScreenTest, InAMultiLineBasicStringTheCharacterAfterABackslashMustBeAscii) {
    EXPECT_EQ(refusal("a = \"\"\"x \\\n    \xC2\xB0 y\"\"\"\n"),
              "2:5: after a line-ending backslash the text must go on with an ASCII character, not character "
              "'\xC2\xB0' (U+00B0)");
    EXPECT_EQ(refusal("a = \"\"\"x \\  \n\n\xE3\x80\x82\"\"\"\n"),
              "3:1: after a line-ending backslash the text must go on with an ASCII character, not character "
              "'\xE3\x80\x82' (U+3002)");
    EXPECT_EQ(refusal("a = \"\"\"\\\xC3\xA9\"\"\"\n"),
              "1:9: character '\xC3\xA9' (U+00E9) cannot follow a backslash (an escape is \\n, \\t, \\uXXXX ...)");
    EXPECT_EQ(refusal("a = \"\"\"x \\\n   y \xC2\xB0 \\\" \\\\\xC2\xB0\"\"\"\n"), "accepted");
    EXPECT_EQ(refusal("a = \"\\\xC3\xA9\"\n"), "accepted"); // toml++ reports the escape; no whitespace test there
}

TEST(TomlScreenTest, ARefusalIsAParseErrorAtTheCharacter) {
    try {
        files::parseTomlText("a = 1\nb = 2 \xEF\xB9\x90\n", "params.toml");
        FAIL() << "parsed";
    } catch (const toml::parse_error& e) {
        EXPECT_EQ(e.source().begin.line, 2u);
        EXPECT_EQ(e.source().begin.column, 7u);
        EXPECT_EQ(*e.source().path, "params.toml");
        EXPECT_NE(std::string(e.description()).find("U+FE50"), std::string::npos) << e.description();
    }
}

// Every character of the ranges toml++ 3.3.0 cannot classify, and a few beyond, at each place where it
// tests for whitespace and inside strings and comments: the text is refused or read, never UB.
TEST(TomlScreenTest, WhatTheScreenLetsThroughTomlReadsWithoutUndefinedBehaviour) {
    const std::vector<std::string> places = {
        " @\n",           "a = 1 @\n",         "a = @\n",     "[@]\n",          "a @= 1\n",
        "a = [1,\n@]\n",  "a = {b = 1 @}\n",   "# @\n",       "a = \"x @\"\n",  "a = '''@'''\n",
        "a = \"\"\"\\@\"\"\"\n", "a = \"\"\"x \\\n  @\"\"\"\n", "a = \"\"\"x \\\n  y@\"\"\"\n", "a = \"\\@\"\n"};
    std::vector<char32_t> characters;
    for (char32_t c = 0x80; c <= 0x500; ++c) characters.push_back(c);
    for (char32_t c = 0x2C60; c <= 0x3070; ++c) characters.push_back(c);
    for (char32_t c = 0xFB20; c <= 0xFF00; ++c) characters.push_back(c);
    for (char32_t c : {0x1680u, 0x180Eu, 0x2000u, 0x200Bu, 0x2028u, 0x205Fu, 0x4E00u, 0x1F527u}) characters.push_back(c);
    int refused = 0;
    int read = 0;
    for (const std::string& place : places) {
        for (char32_t c : characters) {
            std::string text = place;
            text.replace(text.find('@'), 1, utf8(c));
            const bool screened = files::findCharacterTomlCannotRead(text).has_value();
            try {
                files::parseTomlText(text, "sweep.toml");
                ++read;
            } catch (const toml::parse_error&) {
                ++refused;
            }
            if (place.rfind("# ", 0) == 0 || place.find("'''") != std::string::npos) {
                ASSERT_FALSE(screened) << place << " U+" << std::hex << static_cast<unsigned>(c);
            }
        }
    }
    EXPECT_EQ(refused + read, static_cast<int>(places.size() * characters.size()));
    EXPECT_GT(read, static_cast<int>(3 * characters.size())); // comments, strings, literal strings at least
}

} // namespace
} // namespace m350::config
