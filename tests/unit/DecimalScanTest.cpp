// scanDecimal converts the plain numbers of a program without std::from_chars when it can do so
// exactly: every value it gives must be bit-identical to from_chars, and every number it cannot
// convert exactly must be left to it.
#include "core/gcode/DecimalScan.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cstring>
#include <random>
#include <string>

namespace {

using m350::gcode::scanDecimal;

struct Scan {
    bool converted = false;
    double value = 0.0;
    std::size_t end = 0; // where the scan stopped
};

Scan scan(const std::string& text) {
    Scan out;
    out.converted = scanDecimal(text.data(), text.size(), out.end, out.value);
    return out;
}

double fromChars(const std::string& text) {
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    EXPECT_EQ(result.ec, std::errc{}) << text;
    EXPECT_EQ(result.ptr, text.data() + text.size()) << text;
    return value;
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// from_chars does not read "5." or ".5" the way G-code writes them: give it "5.0" / "0.5".
std::string forFromChars(std::string text) {
    if (text.front() == '.') {
        text.insert(0, "0");
    }
    if (text.back() == '.') {
        text += '0';
    }
    return text;
}

void expectExactOrDeclined(const std::string& text) {
    const Scan s = scan(text);
    EXPECT_EQ(s.end, text.size()) << text; // digits and the point are always taken
    if (s.converted) {
        const double expected = fromChars(forFromChars(text));
        EXPECT_TRUE(sameBits(s.value, expected)) << text << ": " << s.value << " vs " << expected;
    }
}

TEST(DecimalScan, ConvertsShortDecimalsAsFromCharsDoes) {
    for (const char* text : {"0", "1", "0.1", "0.2", "0.3", "1.1", "5.", ".5", "12.5", "0.001", "999999999999999",
                             "99999999999999.9", "0.0000000000000000000001", "1.0000000000000000000000",
                             "000000000000000000000012.5", "0000.1", "4503599627370497", "8.765"}) {
        const Scan s = scan(text);
        EXPECT_TRUE(s.converted || std::strlen(text) - (std::strchr(text, '.') ? 1 : 0) > 15) << text;
        expectExactOrDeclined(text);
    }
    EXPECT_TRUE(scan("0.1").converted);
    EXPECT_TRUE(scan("000000000000000000000012.5").converted); // leading zeros are not significant
    EXPECT_TRUE(scan(".5").converted);
    EXPECT_TRUE(scan("5.").converted);
}

TEST(DecimalScan, LeavesNumbersBeyondItsExactRangeToFromChars) {
    // 16 or more significant digits may not fit 2^53; more than 22 after the point have no exact
    // power of ten: both go to the general conversion.
    for (const char* text : {"9007199254740993", "123456789012345678", "12345678901234567890", "0.12345678901234567",
                             "1.00000000000000000000001", "0.00000000000000000000001", "1234567890123456.7"}) {
        EXPECT_FALSE(scan(text).converted) << text;
        EXPECT_EQ(scan(text).end, std::strlen(text)) << text;
    }
}

TEST(DecimalScan, RefusesASecondPointAndStopsAtTheFirstOtherCharacter) {
    Scan twoPoints = scan("1.2.3X");
    EXPECT_FALSE(twoPoints.converted);
    EXPECT_EQ(twoPoints.end, 5u);
    Scan word = scan("12.5Y3");
    EXPECT_TRUE(word.converted);
    EXPECT_EQ(word.end, 4u);
    EXPECT_EQ(word.value, 12.5);
}

TEST(DecimalScan, RandomDecimalsAreBitIdenticalToFromChars) {
    std::mt19937_64 rng(20261124);
    std::uniform_int_distribution<int> digitCount(0, 20);
    std::uniform_int_distribution<int> zeros(0, 4);
    std::uniform_int_distribution<int> digit(0, 9);
    std::uniform_int_distribution<int> shape(0, 3);
    int converted = 0;
    for (int n = 0; n < 200000; ++n) {
        std::string text(static_cast<std::size_t>(zeros(rng)), '0');
        const int whole = digitCount(rng);
        for (int k = 0; k < whole; ++k) {
            text += static_cast<char>('0' + digit(rng));
        }
        if (shape(rng) != 0) {
            text += '.';
            const int fraction = shape(rng) == 3 ? digitCount(rng) + 5 : digitCount(rng);
            for (int k = 0; k < fraction; ++k) {
                text += static_cast<char>('0' + digit(rng));
            }
        }
        if (text.empty() || text == ".") {
            continue;
        }
        const Scan s = scan(text);
        converted += s.converted ? 1 : 0;
        expectExactOrDeclined(text);
        if (HasFailure()) {
            return;
        }
    }
    EXPECT_GT(converted, 50000); // the fast path is really taken, not only declined
}

} // namespace
