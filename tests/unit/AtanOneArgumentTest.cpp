// The one-argument ATAN[x] beside ATAN[a]/[b] and ATAN[a,b]: it answers as ATAN[x]/[1] does on
// the same machine, so FANUC gives 0..360 degrees (NAT = 0) and the M350 -90..90.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using m350::test::lines;

constexpr double kEps = 1e-9;

TEST(AtanOneArgument, FanucAnswersFromZeroTo360) {
    auto run = m350::test::runFanuc(lines({
        "#1 = ATAN[1]", "#2 = ATAN[-1]", "#3 = ATAN[0]", "#4 = ATAN[SQRT[3]]", "#5 = ATAN[-1]/[1]",
        "#6 = ATAN[1] * 2", "#7 = ATAN[#100]", "#8 = ATAN[1]/2", "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(1), 45, kEps);
    EXPECT_NEAR(run.number(2), 315, kEps);
    EXPECT_NEAR(run.number(3), 0, kEps);
    EXPECT_NEAR(run.number(4), 60, kEps);
    EXPECT_NEAR(run.number(5), run.number(2), kEps); // ATAN[x] is ATAN[x]/[1]
    EXPECT_NEAR(run.number(6), 90, kEps);
    EXPECT_NEAR(run.number(7), 0, kEps); // <vacant> reads as 0 in an expression
    EXPECT_NEAR(run.number(8), 22.5, kEps);
}

TEST(AtanOneArgument, M350AnswersFromMinus90To90) {
    auto run = m350::test::runM350(lines({
        "#1 = ATAN[1]", "#2 = ATAN[-1]", "#3 = ATAN[-1,1]", "#4 = ATAN[1000000]", "M30",
    }));
    EXPECT_RUN_OK(run);
    EXPECT_NEAR(run.number(1), 45, kEps);
    EXPECT_NEAR(run.number(2), -45, kEps);
    EXPECT_NEAR(run.number(3), run.number(2), kEps); // ATAN[x] is ATAN[x,1]
    EXPECT_NEAR(run.number(4), 90, 1e-4);
}

TEST(AtanOneArgument, M350RefusesTheSlashFormAtItsColumn) {
    auto run = m350::test::loadProgram(m350::test::m350Machine(), "#1 = 0\n#2 = ATAN[1]/[2]\nM30\n");
    EXPECT_FALSE(run.loaded);
    EXPECT_NE(run.diagnostics().find(run.fileName + ":2:13: ATAN[a]/[b] is not m350 syntax: write ATAN[a,b]"),
              std::string::npos)
        << run.diagnostics();
}

} // namespace
