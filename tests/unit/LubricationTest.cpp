// M10/M11, the M350 firmware's own lubrication codes (润滑), beside M8/M9 (冷却): each switches its
// function's output (params 733-735, 730-732) and, when the output changes, lasts the command's
// response time (params 94, 92). A library handler (O10010, O10011) takes them over as it does
// any M code; the factory's M30 handler runs M5M9M11 at every program end.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

constexpr int kLubricationPin = 9; // OUT09
constexpr int kCoolantPin = 8;     // OUT08

// Lubrication on OUT09, coolant on OUT08, both active high; M10/M11 take 1.5 s, M8/M9 0.5 s.
config::MachineConfig wired() {
    auto cfg = m350Machine();
    cfg.parameters.set(param::kLubricationOutput, kLubricationPin);
    cfg.parameters.set(param::kLubricationOutput + 1, 1);
    cfg.parameters.set(param::kLubricationOutput + 2, 1);
    cfg.parameters.set(param::kLubricationResponse, 1.5);
    cfg.parameters.set(param::kCoolantOutput, kCoolantPin);
    cfg.parameters.set(param::kCoolantOutput + 1, 1);
    cfg.parameters.set(param::kCoolantOutput + 2, 1);
    cfg.parameters.set(param::kCoolantResponse, 0.5);
    return cfg;
}

config::MachineConfig withMLibrary(config::MachineConfig cfg, const std::string& text) {
    cfg.libraries.push_back({writeTempFile(text), gcode::FileRole::MLibrary});
    return cfg;
}

TEST(Lubrication, M10SwitchesTheOutputOnAndM11OffEachLastingParam94) {
    ProgramRun r = runProgram(wired(), lines({"#100 = #[1552+9-1]", "M10", "#101 = #[1552+9-1]", "M11",
                                              "#102 = #[1552+9-1]"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 0);
    EXPECT_EQ(r.number(101), 1);
    EXPECT_EQ(r.number(102), 0);
    EXPECT_NEAR(r.report.simTime, 3.0, 0.01); // two switches of 1.5 s
}

TEST(Lubrication, AnActiveLowOutputAndTheCoolantCodesFollowTheirOwnTriple) {
    auto cfg = wired();
    cfg.parameters.set(param::kLubricationOutput + 2, 0); // 润滑 active at 0
    ProgramRun r = runProgram(cfg, lines({"M11", "#100 = #[1552+9-1]", "M10", "M8", "#101 = #[1552+9-1]",
                                          "#102 = #[1552+8-1]", "M9", "#103 = #[1552+8-1]"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(100), 1); // off: its inactive level
    EXPECT_EQ(r.number(101), 0); // on: its active level
    EXPECT_EQ(r.number(102), 1);
    EXPECT_EQ(r.number(103), 0);
    EXPECT_NEAR(r.report.simTime, 1.5 + 1.5 + 0.5 + 0.5, 0.01);
}

TEST(Lubrication, ACommandThatChangesNothingOrAnUnwiredOutputWaitsForNothing) {
    ProgramRun repeated = runProgram(wired(), lines({"M11", "M9", "M10", "M10"}));
    EXPECT_RUN_OK(repeated);
    EXPECT_NEAR(repeated.report.simTime, 1.5, 0.01); // only the first M10 switched anything

    auto cfg = wired();
    cfg.parameters.set(param::kLubricationOutput + 1, 0); // not enabled on the IO page
    ProgramRun unwired = runProgram(cfg, lines({"M10", "#100 = #[1552+9-1]", "M11"}));
    EXPECT_RUN_OK(unwired);
    EXPECT_EQ(unwired.number(100), 0);
    EXPECT_NEAR(unwired.report.simTime, 0.0, 0.01);
}

// As for M8: the library's O100xx runs instead of the built-in code, and inside it the code is
// the firmware's own again.
TEST(Lubrication, ALibraryHandlerTakesPrecedenceAsForM8) {
    auto cfg = withMLibrary(wired(), lines({"O10010(M10: our own)", "#150 = #150 + 1", "M10", "M99",
                                            "O10008(M8: our own)", "#151 = #151 + 1", "M8", "M99"}));
    ProgramRun r = runProgram(cfg, lines({"M10", "M8", "#100 = #[1552+9-1]", "#101 = #[1552+8-1]", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(150), 1);
    EXPECT_EQ(r.number(151), 1);
    EXPECT_EQ(r.number(100), 1);
    EXPECT_EQ(r.number(101), 1);
}

// The factory's M30 handler (O10030) runs M5M9M11: every program ends without an alarm, and the
// lubrication the program switched on goes off.
TEST(Lubrication, TheFactoryM30HandlerEndsEveryProgram) {
    auto cfg = withMLibrary(wired(), lines({"O10030(M30 程序结束)", "M5M9M11", "#1506 = 30", "#701 = #701 + 1", "M99"}));
    ProgramRun r = runProgram(cfg, lines({"G90 G0 X10 Y10", "M10", "G1 Z-1 F500", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.number(1506), 30);
    EXPECT_EQ(r.number(701), 1);
    EXPECT_EQ(r.report.outputs[kLubricationPin - 1], 0);

    // no handler: the built-in M30 switches lubrication and coolant off too (without waiting)
    ProgramRun plain = runProgram(wired(), lines({"M10", "M8", "M30"}));
    EXPECT_RUN_OK(plain);
    EXPECT_EQ(plain.report.outputs[kLubricationPin - 1], 0);
    EXPECT_EQ(plain.report.outputs[kCoolantPin - 1], 0);
    EXPECT_NEAR(plain.report.simTime, 1.5 + 0.5, 0.01);
}

// On FANUC machines M10/M11 stay the PMC's (the umbrella carousel's clamp, see UmbrellaCarouselTest).
TEST(Lubrication, FanucLeavesM10AndM11ToThePmc) {
    auto cfg = fanucMachine();
    cfg.parameters.set(param::kLubricationOutput, kLubricationPin);
    cfg.parameters.set(param::kLubricationOutput + 1, 1);
    cfg.parameters.set(param::kLubricationOutput + 2, 1);
    ProgramRun r = runProgram(cfg, lines({"M10", "M30"}));
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.outputs[kLubricationPin - 1], 0);
}

} // namespace
