// Issues 11 and 13, the language as a user of m350-sim sees it: what the factory files and the
// vendor's libraries write runs, `check` files each finding under the right kind with its
// file:line:col, and what stays an error says so. The library below is written for these tests in
// the style of the factory's slib-m.nc / slib-g.nc.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace m350::clitest {

namespace {

// O510 X<tool> Z<lift>: notes where the pocket of a tool is and stands over it, lifted.
constexpr const char* kDemoLibrary = "%\n"
                                     "/* slib-demo.nc 演示库: written for the tests in the factory's style.\n"
                                     "   O510 X<tool> Z<lift>: the pocket of a tool, and stand over it lifted.\n"
                                     "*/\n"
                                     "O510(刀位 the pocket of tool X#1, lifted by Z#3)\n"
                                     "/* M100 开始为功能性代码*/\n"
                                     "IF [#1 LT 1] GOTO90\n"
                                     "#100=#[1330+#1-1]+0\n"
                                     "#101=#[1350+#1-1]\n"
                                     "#102=#[1370+#1-1]+#3\n"
                                     "/*\n"
                                     "G53 X#100 Y#101\n"
                                     "G53 Z#102 (旧代码 old code, never run)\n"
                                     "*/\n"
                                     "G90 G53 Z[#[1370+#1-1]]+75 F#4+600\n"
                                     "G91G01Z-#3+#4\n"
                                     "G90\n"
                                     "#1503=-5000(到位 over the pocket).\n"
                                     "M99\n"
                                     "N90 #1503=-5000(刀号错误 no such tool).\n"
                                     "M99\n";

} // namespace

class CliLexicalTest : public CliTest {
  protected:
    // The default machine with the demo library added to its [libraries].
    std::string machineWithDemoLibrary() {
        fs::path machine = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", machine, fs::copy_options::recursive);
        std::ifstream in(machine / "machine.toml");
        std::string toml((std::istreambuf_iterator<char>(in)), {});
        const std::string other = "other = [";
        if (auto at = toml.find(other); at != std::string::npos) {
            toml.insert(at + other.size(), "\"slib-demo.nc\", ");
        } else {
            const std::string key = "[libraries]\n";
            toml.insert(toml.find(key) + key.size(), other + "\"slib-demo.nc\"]\n");
        }
        write("machine/machine.toml", toml);
        write("machine/slib-demo.nc", kDemoLibrary);
        return machine.string();
    }
};

TEST_F(CliLexicalTest, AFactoryStyleLibraryLoadsAndRunsOnTheDefaultMachine) {
    const std::string machine = machineWithDemoLibrary();
    write("use-demo.nc", "M98 P510 X1 Z10\nM30\n");
    ProcessResult checked = sim({"check", "use-demo.nc", "--config", machine});
    EXPECT_EQ(checked.exitStatus, kExitOk) << checked.err;
    json c = output(checked);
    EXPECT_EQ(c.value("status", ""), "ok");
    ASSERT_EQ(c["diagnostics"].size(), 2u) << c; // the two stray dots, notes only
    for (const json& d : c["diagnostics"]) {
        EXPECT_EQ(d.value("file", ""), "slib-demo.nc");
        EXPECT_EQ(d.value("kind", ""), "lint");
        EXPECT_EQ(d.value("severity", ""), "warning");
    }
    EXPECT_EQ(c["diagnostics"][0].value("line", 0), 18);
    EXPECT_EQ(c["diagnostics"][1].value("line", 0), 20);

    ProcessResult r = sim({"run", "use-demo.nc", "--config", machine, "--print", "100,101,102"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    expectRunContract(j);
    EXPECT_EQ(j.value("status", ""), "ok") << j["alarm"];
    EXPECT_EQ(j["vars"]["100"], 50.0);  // param 830, T01 pocket X
    EXPECT_EQ(j["vars"]["101"], 5.0);   // param 850
    EXPECT_EQ(j["vars"]["102"], -70.0); // param 870 + 10
    EXPECT_DOUBLE_EQ(j["machine"]["Z"].get<double>(), -15.0); // -80 + 75, then 10 down
    EXPECT_EQ(j["messages"], json::array({"到位 over the pocket"}));
}

TEST_F(CliLexicalTest, CheckNamesTheLineOfAnErrorAfterAMultiLineComment) {
    write("comment.nc", "G0 X1\n/*\nG0 X2\n(a)\n*/\nG1 X\nM30\n");
    ProcessResult r = sim({"check", "comment.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_EQ(lines(r.err), std::vector<std::string>{"comment.nc:6:4: address X needs a value, found the end of "
                                                     "the line"});
    json j = output(r);
    ASSERT_EQ(j["diagnostics"].size(), 1u);
    EXPECT_EQ(j["diagnostics"][0].value("line", 0), 6);
    EXPECT_EQ(j["diagnostics"][0].value("kind", ""), "syntax");
}

TEST_F(CliLexicalTest, AnUnclosedBlockCommentIsASyntaxErrorAtItsOpening) {
    write("open.nc", "G0 X1\n  /* 开始\nG0 X2\nM30\n");
    ProcessResult r = sim({"run", "open.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    json alarm = output(r)["alarm"];
    EXPECT_EQ(alarm.value("code", ""), "syntax_error");
    EXPECT_EQ(alarm.value("line", 0), 2);
    EXPECT_EQ(alarm.value("column", 0), 3);
    EXPECT_EQ(alarm.value("message", ""), "the comment '/*' is not closed with '*/' before the end of the file");
}

TEST_F(CliLexicalTest, AGotoWithoutItsLabelIsAFlowFindingAndAlarmsOnlyWhenReached) {
    const char* program = "#1=5\nIF [#1 NE 99] GOTO34\nGOTO33\nN34 M30\n";
    write("goto.nc", program);
    ProcessResult checked = sim({"check", "goto.nc"});
    EXPECT_EQ(checked.exitStatus, kExitError);
    json c = output(checked);
    ASSERT_EQ(c["diagnostics"].size(), 1u) << c;
    EXPECT_EQ(c["diagnostics"][0].value("kind", ""), "flow");
    EXPECT_EQ(lines(checked.err), std::vector<std::string>{"goto.nc:3:5: GOTO33: there is no N33 in this program"});
    runExpecting("goto.nc", program, kExitOk, "ok");
    json reached = runExpecting("reached.nc", "#1=99\nIF [#1 NE 99] GOTO34\nGOTO33\nN34 M30\n", kExitAlarm, "alarm");
    EXPECT_EQ(reached["alarm"].value("code", ""), "goto_missing_label");
    EXPECT_EQ(reached["alarm"].value("line", 0), 3);
}

TEST_F(CliLexicalTest, TextNoBlockReachesIsALintAndTheProgramRuns) {
    const char* program = "#100=1\nM30\n#\n";
    write("tail.nc", program);
    ProcessResult checked = sim({"check", "tail.nc", "--dialect", "fanuc"});
    json c = output(checked);
    ASSERT_EQ(c["diagnostics"].size(), 1u) << c;
    EXPECT_EQ(c["diagnostics"][0].value("kind", ""), "lint");
    EXPECT_EQ(c["diagnostics"][0].value("line", 0), 3);
    ProcessResult r = sim({"run", "tail.nc", "--dialect", "fanuc", "--print", "100"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(output(r)["vars"]["100"], 1.0);
}

TEST_F(CliLexicalTest, FanucSpacesInsideNumbersAndVariableNumbers) {
    write("spaced.nc", "# 1 0 0 = 2 5\nG 0 1 X 1 0 . 5 F 1 0 0 0\nIF [#100 GT ABS[-2]] GOTO 9\n#100 = 0\nN9 M30\n");
    ProcessResult r = sim({"run", "spaced.nc", "--dialect", "fanuc", "--print", "100"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"]["100"], 25.0);
    EXPECT_DOUBLE_EQ(j["work"]["X"].get<double>(), 10.5);
}

TEST_F(CliLexicalTest, CrOnlyLineEndsKeepBlocksApart) {
    write("mac.nc", "#100=1\r#101=2\r#102=#100+#101\rG0 X\rM30\r");
    ProcessResult r = sim({"check", "mac.nc"});
    EXPECT_EQ(lines(r.err), std::vector<std::string>{"mac.nc:4:4: address X needs a value, found the end of the line"});
    write("mac.nc", "#100=1\r#101=2\r#102=#100+#101\rM30\r");
    ProcessResult run = sim({"run", "mac.nc", "--print", "102"});
    EXPECT_EQ(run.exitStatus, kExitOk) << run.err;
    EXPECT_EQ(output(run)["vars"]["102"], 3.0);
}

TEST_F(CliLexicalTest, AnExponentIsASyntaxErrorNotIgnored) {
    json j = runExpecting("dwell.nc", "G4 P1E3\nM30\n", kExitError, "error");
    EXPECT_EQ(j["alarm"].value("line", 0), 1);
    EXPECT_EQ(j["alarm"].value("column", 0), 5);
    EXPECT_EQ(j["alarm"].value("message", ""),
              "'1E3' is not a G-code number: there is no exponent (E) notation; write the number in digits");
}

TEST_F(CliLexicalTest, ALabelBeyondEightDigitsIsRefused) {
    json j = runExpecting("far.nc", "GOTO 99999999999\nN99999999999 M30\n", kExitError, "error");
    EXPECT_EQ(j["alarm"].value("message", ""), "GOTO99999999999: sequence numbers run from 0 to 99999999 (8 digits)");
    EXPECT_EQ(j["diagnostics"].size(), 2u);
}

} // namespace m350::clitest
