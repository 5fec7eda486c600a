// formatMessageText, and the #1503 status-line messages built from it.
#include "RunProgram.h"

#include "core/macro/MessageText.h"

#include <gtest/gtest.h>

#include <string>

using m350::macro::formatMessageText;
using m350::test::lines;
using m350::test::runM350;

namespace {

std::string format(std::string_view text, double a = 0, double b = 0, double c = 0, double d = 0) {
    const double values[4] = {a, b, c, d};
    return formatMessageText(text, values);
}

TEST(MessageText, PlainTextIsCopied) {
    EXPECT_EQ(format("X,Y,Z axes not homed!"), "X,Y,Z axes not homed!");
    EXPECT_EQ(format(""), "");
    EXPECT_EQ(format("当前刀具号不能为0,请手动装一把刀!"), "当前刀具号不能为0,请手动装一把刀!");
}

TEST(MessageText, PlaceholdersTakeTheValuesInOrder) {
    EXPECT_EQ(format("T%.0f", 5), "T5");
    EXPECT_EQ(format("T%.0f -> T%.0f", 3, 7), "T3 -> T7");
    EXPECT_EQ(format("Z=%.3f", 1.5), "Z=1.500");
    EXPECT_EQ(format("%.0f %.1f %.2f %.3f", 1, 2, 3, 4), "1 2.0 3.00 4.000");
    EXPECT_EQ(format("X%.3f Y%.3f", -12.5, 0.0004), "X-12.500 Y0.000");
}

TEST(MessageText, PlaceholdersRound) {
    EXPECT_EQ(format("%.0f", 2.6), "3");
    EXPECT_EQ(format("%.3f", 60.6204), "60.620");
    EXPECT_EQ(format("%.3f", 1.2346), "1.235");
    EXPECT_EQ(format("%.1f", -0.25001), "-0.3");
}

TEST(MessageText, DoublePercentIsALiteralPercent) {
    EXPECT_EQ(format("100%%"), "100%");
    EXPECT_EQ(format("%.0f%% done", 42), "42% done");
    EXPECT_EQ(format("%%%%"), "%%");
    EXPECT_EQ(format("%%.0f", 9), "%.0f"); // the escaped % does not start a placeholder
}

TEST(MessageText, StrayPercentIsKeptAsWritten) {
    EXPECT_EQ(format("50% done"), "50% done");
    EXPECT_EQ(format("ends with %"), "ends with %");
    EXPECT_EQ(format("%d and %s", 1, 2), "%d and %s");
    EXPECT_EQ(format("%.f", 3), "%.f");
    EXPECT_EQ(format("%.3", 3), "%.3");
    EXPECT_EQ(format("%.x5", 3), "%.x5");
}

TEST(MessageText, AtMostFourValues) {
    EXPECT_EQ(format("%.0f %.0f %.0f %.0f %.0f", 1, 2, 3, 4), "1 2 3 4 %.0f");
}

TEST(MessageText, StrayPercentDoesNotConsumeAValue) {
    EXPECT_EQ(format("5% T%.0f", 8), "5% T8");
}

// ---------------------------------------------------------------- #1503 in a run

TEST(MessageVariable, Message1503FillsPlaceholdersFrom1510To1513) {
    auto run = runM350(lines({
        "#1510 = 3",
        "#1511 = 2.5",
        "#1512 = 60.62",
        "#1513 = 7",
        "#1503 = 1(T%.0f Z%.3f W%.1f N%.0f 100%%)",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 1u);
    EXPECT_EQ(run.report.messages[0], "T3 Z2.500 W60.6 N7 100%");
}

TEST(MessageVariable, MessagesAppearInProgramOrder) {
    auto run = runM350(lines({
        "#1503 = 1(first)",
        "#1510 = 1",
        "WHILE [#1510 <= 3] DO1",
        "#1503 = 1(pass %.0f)",
        "#1510 = #1510 + 1",
        "END1",
        "M30",
    }));
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 4u);
    EXPECT_EQ(run.report.messages[0], "first");
    EXPECT_EQ(run.report.messages[1], "pass 1");
    EXPECT_EQ(run.report.messages[3], "pass 3");
}

TEST(MessageVariable, Value1000ClearsInsteadOfPosting) {
    auto run = runM350(lines({"#1503 = 1(tool change)", "#1503 = 1000", "#1503 = 1000(not shown)", "M30"}));
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 1u);
    EXPECT_EQ(run.report.messages[0], "tool change");
}

TEST(MessageVariable, ValuesAreReadWhenTheMessageIsWritten) {
    auto run = runM350(lines({"#1510 = 4", "#1503 = 1(T%.0f)", "#1510 = 9", "M30"}));
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 1u);
    EXPECT_EQ(run.report.messages[0], "T4");
}

} // namespace

namespace {

TEST(AlarmTextFields, VariablesAreFilledInWithAtMostThreeDecimals) {
    auto read = [](int n) -> std::optional<double> {
        if (n == 20) {
            return 1.0;
        }
        if (n == 32) {
            return 0.6200000000001;
        }
        return std::nullopt;
    };
    EXPECT_EQ(m350::macro::expandVariableFields("tool {#20} broken: {#32} mm short", read), "tool 1 broken: 0.62 mm short");
    EXPECT_EQ(m350::macro::expandVariableFields("{#7} {#} {x} {#12345} {#20", read), "vacant {#} {x} {#12345} {#20");
}

} // namespace
