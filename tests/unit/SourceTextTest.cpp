#include "core/gcode/SourceText.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include <sys/stat.h>

using namespace m350::gcode;

namespace {

// "(换刀程序)" as the M350 panel stores it.
constexpr std::string_view kGbkToolChange = "(\xBB\xBB\xB5\xB6\xB3\xCC\xD0\xF2)";

SourceText expectText(const std::variant<SourceText, SourceReadError>& result) {
    if (const auto* error = std::get_if<SourceReadError>(&result)) {
        ADD_FAILURE() << "unexpected error: " << error->message;
        return {};
    }
    return std::get<SourceText>(result);
}

std::string expectError(const std::variant<SourceText, SourceReadError>& result) {
    if (const auto* text = std::get_if<SourceText>(&result)) {
        ADD_FAILURE() << "unexpected success, decoded as " << encodingName(text->encoding);
        return {};
    }
    return std::get<SourceReadError>(result).message;
}

std::string tempPath(const std::string& suffix) {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    return testing::TempDir() + "m350_" + info->name() + suffix;
}

}  // namespace

TEST(SourceText, EncodingNames) {
    EXPECT_EQ(encodingName(TextEncoding::Utf8), "UTF-8");
    EXPECT_EQ(encodingName(TextEncoding::Gbk), "GBK");
}

TEST(SourceText, AsciiIsUtf8) {
    const auto text = expectText(decodeSource("a.nc", "G0 X1\r\nM30\r\n"));
    EXPECT_EQ(text.path, "a.nc");
    EXPECT_EQ(text.text, "G0 X1\r\nM30\r\n");
    EXPECT_EQ(text.encoding, TextEncoding::Utf8);
}

TEST(SourceText, EmptyIsUtf8) {
    const auto text = expectText(decodeSource("e.nc", ""));
    EXPECT_EQ(text.text, "");
    EXPECT_EQ(text.encoding, TextEncoding::Utf8);
}

TEST(SourceText, Utf8Chinese) {
    const auto text = expectText(decodeSource("u.nc", "(换刀程序)\nT1 M6\n"));
    EXPECT_EQ(text.text, "(换刀程序)\nT1 M6\n");
    EXPECT_EQ(text.encoding, TextEncoding::Utf8);
}

TEST(SourceText, Utf8BomIsStripped) {
    const auto text = expectText(decodeSource("b.nc", "\xEF\xBB\xBF(换刀)\nM30\n"));
    EXPECT_EQ(text.text, "(换刀)\nM30\n");
    EXPECT_EQ(text.encoding, TextEncoding::Utf8);
}

TEST(SourceText, GbkIsDecodedToUtf8) {
    const auto text = expectText(decodeSource("g.nc", std::string(kGbkToolChange) + "\r\nT1 M6\r\n"));
    EXPECT_EQ(text.text, "(换刀程序)\r\nT1 M6\r\n");
    EXPECT_EQ(text.encoding, TextEncoding::Gbk);
}

TEST(SourceText, StrictUtf8RejectsOverlongSurrogateAndOutOfRange) {
    // Each is malformed UTF-8; whatever GB18030 makes of it, it must not be accepted as UTF-8.
    for (const std::string_view bytes : {"\xC0\xAF", "\xE0\x80\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xE4\xB8"}) {
        const auto result = decodeSource("s.nc", bytes);
        const auto* text = std::get_if<SourceText>(&result);
        EXPECT_TRUE(text == nullptr || text->encoding == TextEncoding::Gbk) << "bytes size " << bytes.size();
    }
    EXPECT_EQ(expectText(decodeSource("s.nc", "\xC0\xAF")).text, "蜡");
}

TEST(SourceText, InvalidInBothReportsLineAndColumn) {
    EXPECT_EQ(expectError(decodeSource("x.nc", "G0 X1\nG1 Y2\nM30 (\xFF)\n")),
              "file is neither valid UTF-8 nor GBK (first bad byte at line 3, column 6)");
}

TEST(SourceText, ErrorPositionFollowsTheEncodingThatGotFurther) {
    // Valid GBK up to the stray 0x80; UTF-8 already fails at the first Chinese byte.
    EXPECT_EQ(expectError(decodeSource("g.nc", std::string(kGbkToolChange) + "\nG1 X1 \x80\n")),
              "file is neither valid UTF-8 nor GBK (first bad byte at line 2, column 7)");
    // Valid UTF-8 up to the 0xFF; GB18030 already fails inside "中".
    EXPECT_EQ(expectError(decodeSource("u.nc", "(中)\xFF")),
              "file is neither valid UTF-8 nor GBK (first bad byte at line 1, column 6)");
    // Columns count the BOM bytes, which are part of the file's first line.
    EXPECT_EQ(expectError(decodeSource("u.nc", "\xEF\xBB\xBF(中)\xFF")),
              "file is neither valid UTF-8 nor GBK (first bad byte at line 1, column 9)");
}

TEST(SourceText, ReadMissingFile) {
    const std::string path = tempPath("_does_not_exist.nc");
    std::remove(path.c_str());
    const auto result = readSourceFile(path);
    ASSERT_TRUE(std::holds_alternative<SourceReadError>(result));
    EXPECT_EQ(std::get<SourceReadError>(result).path, path);
    EXPECT_EQ(std::get<SourceReadError>(result).message, "cannot open file: No such file or directory");
}

TEST(SourceText, ReadGbkFile) {
    const std::string path = tempPath(".nc");
    {
        std::ofstream out(path, std::ios::binary);
        out << kGbkToolChange << "\r\nT1 M6\r\nM99\r\n";
    }
    const auto text = expectText(readSourceFile(path));
    std::remove(path.c_str());
    EXPECT_EQ(text.path, path);
    EXPECT_EQ(text.text, "(换刀程序)\r\nT1 M6\r\nM99\r\n");
    EXPECT_EQ(text.encoding, TextEncoding::Gbk);
}

// A UTF-8 file is parsed where it lies (mapped): the text stays valid while the SourceText lives,
// even after the file is removed, and copies share it.
TEST(SourceText, ReadUtf8FileKeepsItsTextAlive) {
    const std::string path = tempPath(".nc");
    {
        std::ofstream out(path, std::ios::binary);
        out << "\xEF\xBB\xBF(换刀)\nG1 X1\n";
    }
    SourceText copy;
    {
        const auto text = expectText(readSourceFile(path));
        std::remove(path.c_str());
        EXPECT_EQ(text.encoding, TextEncoding::Utf8);
        copy = text;
    }
    EXPECT_EQ(copy.text, "(换刀)\nG1 X1\n");
}

TEST(SourceText, ReadEmptyFile) {
    const std::string path = tempPath(".nc");
    { std::ofstream out(path, std::ios::binary); }
    const auto text = expectText(readSourceFile(path));
    std::remove(path.c_str());
    EXPECT_EQ(text.text, "");
    EXPECT_EQ(text.encoding, TextEncoding::Utf8);
}

// Issue 13: /dev/zero or a FIFO as a program read until memory ran out (or waited for a writer
// forever); a huge file is refused before it is mapped.
TEST(SourceText, ReadRefusesFifosDevicesAndHugeFiles) {
    EXPECT_EQ(expectError(readSourceFile("/dev/zero")), "cannot read file: it is a device, not a program file");
    const std::string fifo = tempPath(".fifo");
    std::remove(fifo.c_str());
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(expectError(readSourceFile(fifo)), "cannot read file: it is a FIFO (named pipe), not a program file");
    std::remove(fifo.c_str());

    const std::string huge = tempPath("_huge.nc");
    {
        std::ofstream out(huge, std::ios::binary);
    }
    std::filesystem::resize_file(huge, kMostProgramBytes + 1); // sparse: no disk used
    EXPECT_NE(expectError(readSourceFile(huge)).find("program files above 4095 MiB are refused"), std::string::npos);
    std::remove(huge.c_str());
}

// A program above 256 MiB is parsed a chunk at a time from the mapped file, which only UTF-8
// allows: a large GBK file would be decoded into memory whole, so it is refused, naming the byte.
TEST(SourceText, AProgramAbove256MiBMustBeUtf8) {
    const std::string big = tempPath("_big_gbk.nc");
    {
        std::ofstream out(big, std::ios::binary);
        out << std::string(300, 'G') << "\n(\xB5\xB6)\n"; // GBK for 刀
    }
    std::filesystem::resize_file(big, kMostSourceBytes + 1); // the rest NUL bytes, sparse
    const auto source = readSourceFile(big);
    ASSERT_TRUE(std::holds_alternative<SourceReadError>(source));
    const SourceReadError& error = std::get<SourceReadError>(source);
    EXPECT_EQ(error.line, 2u);
    EXPECT_EQ(error.column, 2u);
    EXPECT_NE(error.message.find("256 MiB and not UTF-8"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("must be UTF-8"), std::string::npos) << error.message;
    std::remove(big.c_str());
}

// Issue 13: encoding errors were placed at 0:0 and a UTF-16 file was "neither UTF-8 nor GBK".
TEST(SourceText, EncodingErrorsArePlacedAndUtf16IsNamed) {
    const auto bad = decodeSource("bad.nc", "G0 X1\n(\xFF\xFF)\n");
    ASSERT_TRUE(std::holds_alternative<SourceReadError>(bad));
    EXPECT_EQ(std::get<SourceReadError>(bad).line, 2u);
    EXPECT_EQ(std::get<SourceReadError>(bad).column, 2u);
    const Diagnostic d = diagnosticOf(std::get<SourceReadError>(bad));
    EXPECT_TRUE(d.unreadable);
    EXPECT_EQ(formatDiagnostic(d), "bad.nc:2:2: file is neither valid UTF-8 nor GBK (first bad byte at line 2, column 2)");

    using namespace std::string_view_literals;
    for (std::string_view utf16 : {"\xFF\xFEG\0" "0\0 \0X\0" "1\0\n\0"sv, "G\0" "0\0 \0X\0" "1\0\n\0"sv}) {
        EXPECT_EQ(expectError(decodeSource("u16.nc", utf16)), "file is UTF-16: save it as UTF-8 or GBK");
    }
}
