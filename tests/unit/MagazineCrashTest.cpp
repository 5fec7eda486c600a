// The training scenarios of the default machine's rack: the manual's O20000 with one line made
// wrong (or one parameter), and the crash or drop the real machine would suffer, reported on the
// line that caused it. A modified O20000 in the program file wins over the machine's slib-g.nc.
#include "RunProgram.h"
#include "ShippedMacros.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

// A bundled machine's O20000, from its O line to `until` (empty: to the end of slib-g.nc).
std::string shippedO20000(const std::string& machine = config::kDefaultMachine,
                          const std::string& until = "// Canned drilling cycles") {
    std::string all = shippedLibrary(machine);
    std::size_t begin = all.find("\nO20000(") + 1;
    EXPECT_NE(begin, 0u);
    std::size_t end = until.empty() ? std::string::npos : all.find(until);
    return all.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The main program `before` + "T2" + "M30", then O20000 with `wrong` put in place of `right`.
// Returns the run and the line (in the program file) where `wrong` stands.
struct Scenario {
    ProgramRun run;
    std::uint32_t line = 0;
};

Scenario change(const std::string& right, const std::string& wrong, const std::string& before = "",
                config::MachineConfig cfg = bundledMachine()) {
    std::string program = before + "T2\nM30\n" + withLine(shippedO20000(), right, wrong);
    Scenario s{runProgram(std::move(cfg), program), 0};
    s.line = lineOf(program, wrong.empty() ? "\n" : wrong);
    return s;
}

void expectCrash(const Scenario& s, const std::string& message) {
    ASSERT_TRUE(s.run.report.alarm.has_value()) << "no crash";
    EXPECT_EQ(s.run.report.alarm->code, AlarmCode::Crash) << s.run.alarmText();
    EXPECT_EQ(s.run.report.alarm->file, s.run.fileName);
    EXPECT_EQ(s.run.report.alarm->message, message);
}

TEST(MagazineCrash, TheShippedChangeRunsAndEveryToolEndsWhereItBelongs) {
    Scenario s = change("", "");
    EXPECT_RUN_OK(s.run);
    EXPECT_EQ(s.run.report.tool, 2);
    EXPECT_EQ(s.run.report.pockets.at(1), 1);
    EXPECT_EQ(s.run.report.pockets.at(2), 0);
    EXPECT_EQ(s.run.number(1300), 2);
}

TEST(MagazineCrash, ReturningTheToolToTheTargetsPocket) {
    // the current tool's X taken from the target's pocket: T1 goes into pocket 2, where T2 is
    Scenario s = change("G53 X#[1330+#1300-1] F#1311", "G53 X#[1330+#1-1] F#1311");
    expectCrash(s, "T1 in the spindle ran into T2 in pocket 2 (moving from X110.000 Y60.000 Z-80.000 to X110.000 "
                   "Y5.000 Z-80.000)");
    EXPECT_EQ(s.run.report.alarm->line, s.line + 2); // the Y slide two lines further on
}

TEST(MagazineCrash, MovingXBeforeTheToolLeavesItsFork) {
    Scenario s = change("G53 Y#1309 F#1313                   //slide the tool out", "G53 X0 F#1311 //wrong:");
    expectCrash(s, "moved X while T2 was clamped in the fork of pocket 2: the fork and the tool are wrecked at "
                   "X110.000 Y5.000 Z-80.000");
    EXPECT_EQ(s.run.report.alarm->line, s.line);
}

TEST(MagazineCrash, ReleasingBeforeTheToolIsInItsPocketDropsIt) {
    Scenario s = change("G53 Y#[1350+#1300-1] F#1313         //slide the tool into its fork (param 813)\n"
                        "#[1552+#20-1] = 1                   //release (松刀)",
                        "#[1552+#20-1] = 1 //wrong: released too early\n"
                        "G53 Y#[1350+#1300-1] F#1313");
    expectCrash(s, "T1 dropped: the drawbar was released at X50.000 Y60.000 Z-80.000 with no pocket under the tool "
                   "(it fell onto the table)");
    EXPECT_EQ(s.run.report.alarm->line, s.line);
    EXPECT_EQ(s.run.report.tool, 0);
}

TEST(MagazineCrash, ComingDownOntoTheToolWithTheSpindleTurning) {
    // no M05 and no wait: the spindle started by the program is still turning
    Scenario s = change("M05                                 //stop the spindle\n"
                        "WHILE [#[1520+#13-1] NE 0] DO1      //wait for IN07 = 0\n"
                        "G04 P10\n"
                        "END1",
                        "", "M03 S1000\n");
    expectCrash(s, "came down onto T2 in pocket 2 with the spindle turning: stop it (M05) and wait for it (M300) first");
}

TEST(MagazineCrash, AWrongChangeHeightParameterDropsTheTool) {
    auto cfg = bundledMachine();
    cfg.parameters.set(807, -60); // Z down 20 mm too high: the tool never reaches its fork
    Scenario s = change("", "", "", cfg);
    expectCrash(s, "T1 dropped: the drawbar was released at X50.000 Y5.000 Z-60.000 with no pocket under the tool "
                   "(it fell onto the table)");
}

TEST(MagazineCrash, FollowRowSlideOutBeforeTheToolIsDownThenComingDownOntoTheFork) {
    // the follow-row O20000 with the slide pushed out while the tool is still up: the tool then
    // comes down onto the fork from above
    std::string o20000 = shippedO20000("m350-follow-row", "");
    const std::string down = "G53 Z#[1370+#1300-1] F#1319         //down to fork height, the slide still in\n";
    const std::string out = "M300                                //the spindle has stopped\n"
                            "M152                                //slide out: the fork takes the tool\n"
                            "M303\n";
    ASSERT_NE(o20000.find(down + out), std::string::npos);
    o20000.replace(o20000.find(down + out), (down + out).size(), out + down);
    std::string program = "T2\nM30\n" + o20000;
    ProgramRun r = runProgram(bundledMachine("m350-follow-row"), program);
    ASSERT_TRUE(r.report.alarm.has_value());
    EXPECT_EQ(r.report.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.report.alarm->message, "T1 in the spindle hit the fork of pocket 1: a tool enters it along Y only "
                                       "(moving from X100.000 Y0.000 Z0.000 to X100.000 Y0.000 Z-90.000)");
    EXPECT_EQ(r.report.alarm->line, lineOf(program, down));
}

TEST(MagazineCrash, TopLoadingWithTheChangeHeightTooLowHitsAFork) {
    auto cfg = bundledMachine("m350-rack-top");
    cfg.parameters.set(806, -70); // "Z up" 70 mm down: the tool travels at fork height
    ProgramRun r = runProgram(std::move(cfg), lines({"T2", "M30"}));
    ASSERT_TRUE(r.report.alarm.has_value());
    EXPECT_EQ(r.report.alarm->code, AlarmCode::Crash);
    EXPECT_EQ(r.report.alarm->message,
              "T1 in the spindle hit the fork of pocket 1: a tool enters it along Z only (moving from X5.000 Y5.000 "
              "Z-70.000 to X100.000 Y400.000 Z-70.000)");
    EXPECT_EQ(r.report.alarm->file, "slib-g.nc");
    EXPECT_EQ(r.report.alarm->line, 25u); // G53 X#[1330+#1300-1] Y#[1350+#1300-1] F#1311
}

} // namespace
