// Tool data as the source documents write it (issue 24), through m350-sim as a user runs it: the
// tool the JSON reports after a FANUC M06, the umbrella carousel refusing a T it has not at the T
// word, FANUC offset memory C (G10 L10-L13, #2001-#2400), the breakage article's calibration
// program as written, FANUC tool life from the control's parameters, and LinuxCNC's tool table
// codes (G10 L0, M61, G43.1, the random changer).
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

namespace {

std::string bundled(const std::string& name) {
    return std::string(M350_MACHINES_DIR) + "/" + name;
}

class CliToolDataTest : public CliTest {
  protected:
    // A copy of a bundled machine folder at `machine/`, which runs may write.
    void copyMachine(const std::string& name) {
        fs::copy(fs::path(M350_MACHINES_DIR) / name, dir_ / "machine", fs::copy_options::recursive);
    }
    json run(const std::string& program, const std::string& text, std::vector<std::string> options,
             int exitStatus = kExitOk) {
        write(program, text);
        std::vector<std::string> args{"run", program};
        args.insert(args.end(), options.begin(), options.end());
        ProcessResult r = sim(args);
        last_ = r;
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err << r.out;
        return output(r);
    }
    ProcessResult last_;
};

} // namespace

// One truth: on a FANUC without a changer M06 is the operator's change by hand, so the tool T
// selected is the spindle's, in "tool" as in #4120 and in the tool life's tool in use.
TEST_F(CliToolDataTest, FanucM06PutsTheSelectedToolInTheSpindleOfTheReport) {
    copyMachine("fanuc-0i");
    json plain = run("t1.nc", "T1 M6\nM30\n", {"--config", "machine", "--print", "4120"});
    EXPECT_EQ(plain["tool"], 1);
    EXPECT_EQ(plain["vars"]["4120"], 1.0);

    json selectedOnly = run("t2.nc", "T2\nM30\n", {"--config", "machine"});
    EXPECT_EQ(selectedOnly["tool"], 0) << "T alone selects; only M06 changes";

    run("enter.nc", "G10 L3\nP1 L2 Q1\nT11 H11 D31\nT12 H12 D32\nG11\nM30\n", {"--config", "machine"});
    json group = run("group.nc", "T101 M6\nM30\n", {"--config", "machine", "--print", "4120"});
    EXPECT_EQ(group["tool"], 11);
    EXPECT_EQ(group["vars"]["4120"], 11.0);
    EXPECT_EQ(group["tool_life"]["in_use"]["tool"], 11);
}

// The carousel's PMC checks the T code when the block starts: T13 on a 12-pocket carousel stops at
// the T word, before O9001 orients the spindle or moves Z, whatever the block holds.
TEST_F(CliToolDataTest, UmbrellaRefusesATItHasNotAtTheTWordBeforeAnythingMoves) {
    json before = run("t13.nc", "G91 G0 Z-5.\nM06 T13\nM30\n", {"--config", bundled("fanuc-umbrella"), "--tool", "4"},
                      kExitAlarm);
    EXPECT_EQ(before["alarm"]["code"], "invalid_argument");
    EXPECT_EQ(before["alarm"]["line"], 2);
    EXPECT_EQ(before["alarm"]["column"], 5);
    EXPECT_NE(last_.err.find("t13.nc:2:5: "), std::string::npos) << last_.err;
    EXPECT_DOUBLE_EQ(before["machine"]["Z"].get<double>(), -5.0) << "Z stayed where line 1 left it";
    EXPECT_EQ(before["tool"], 4);
    EXPECT_EQ(before["outputs"][0], 0) << "the drawbar was never released";

    json alone = run("alone.nc", "T0\nT12\nT-1 G0 Z-3.\nM30\n", {"--config", bundled("fanuc-umbrella"), "--tool", "4"},
                     kExitAlarm);
    EXPECT_EQ(alone["alarm"]["line"], 3);
    EXPECT_EQ(alone["alarm"]["column"], 1);
    EXPECT_DOUBLE_EQ(alone["machine"]["Z"].get<double>(), 0.0) << "the block's own move did not start";

    json argument = run("arg.nc", "O1\nG65 P2 T99\nM30\nO2\nM99\n", {"--config", bundled("fanuc-umbrella")});
    EXPECT_EQ(argument["status"], "ok") << "a macro's T argument selects no tool";
}

// FANUC offset memory C (fanuc-ts27r): G10 L10 / L11 / L12 / L13 P R write H geometry, H wear, D
// geometry, D wear, each only its own register; #2001-#2200 read the H wear and #2201-#2400 the H
// geometry; G43 applies geometry + wear. tool.tbl keeps the geometry as Z and D, the wear in {}.
TEST_F(CliToolDataTest, FanucMemoryCWritesEachRegisterItsGTenLNames) {
    copyMachine("fanuc-ts27r");
    json j = run("c.nc",
                 "G10 L10 P1 R20.\nG10 L11 P1 R-0.1\nG10 L12 P2 R4.\nG91 G10 L13 P2 R0.25\nG10 L13 P2 R0.5\nG90\n"
                 "#100 = #2201\n#101 = #2001\n#102 = #2202\nG43 H1 G0 Z0\n#103 = #5023\nM30\n",
                 {"--config", "machine", "--print", "100,101,102,103", "--tools-out", "out.tbl"});
    EXPECT_EQ(j["vars"]["100"], 20.0) << "L10: H geometry";
    EXPECT_EQ(j["vars"]["101"], -0.1) << "L11: H wear";
    EXPECT_EQ(j["vars"]["102"], 95.5) << "tool 2's length untouched by L12/L13";
    EXPECT_NEAR(j["vars"]["103"].get<double>(), 19.9, 1e-9) << "G43 H1: geometry + wear";
    std::ifstream in(dir_ / "out.tbl");
    std::stringstream table;
    table << in.rdbuf();
    EXPECT_NE(table.str().find("T1 P1 Z20 D10 ;end mill D10 {hwear=-0.1}"), std::string::npos)
        << "L10 wrote the length, not the diameter:\n" << table.str();
    EXPECT_NE(table.str().find("T2 P2 Z95.5 D8 ;face mill D16 {dwear=0.75}"), std::string::npos)
        << "L12 the D geometry (radius 4), L13 under G91 added to the D wear:\n" << table.str();

    json refused = run("l1.nc", "G10 L1 P1 R5.\nM30\n", {"--config", "machine"}, kExitAlarm);
    EXPECT_EQ(refused["alarm"]["code"], "invalid_word");
    EXPECT_EQ(refused["alarm"]["column"], 5) << "at the L word";
    EXPECT_NE(last_.err.find("l1.nc:1:5: "), std::string::npos) << last_.err;
    EXPECT_NE(refused["alarm"]["message"].get<std::string>().find("offset memory C"), std::string::npos);
}

// FANUC offset memory A (fanuc-0i): one value per offset, G10 L11 P R or its older L1 P R; L10 is
// memory C's and refused rather than written somewhere else. LinuxCNC's form, with axis words,
// still writes the table (R its radius).
TEST_F(CliToolDataTest, FanucMemoryAWritesItsOneValueAndRefusesMemoryCForms) {
    copyMachine("fanuc-0i");
    write("machine/tool.tbl", "T1 P1 Z0 D10 ;end mill\nT2 P2\n");
    json j = run("a.nc", "G10 L11 P1 R20.\n#100 = #2001\nG10 L1 P2 R7.\n#101 = #2002\nM30\n",
                 {"--config", "machine", "--print", "100,101", "--tools-out", "out.tbl"});
    EXPECT_EQ(j["vars"]["100"], 20.0);
    EXPECT_EQ(j["vars"]["101"], 7.0) << "L1 P R is L11's older form on memory A";
    std::ifstream in(dir_ / "out.tbl");
    std::stringstream table;
    table << in.rdbuf();
    EXPECT_NE(table.str().find("T1 P1 Z20 D10 ;end mill"), std::string::npos) << table.str();
    EXPECT_NE(table.str().find("T2 P2 Z7"), std::string::npos) << "the length, not D = 14:\n" << table.str();

    json refused = run("l10.nc", "G0 X1.\nG10 L10 P1 R20.\nM30\n", {"--config", "machine", "--print", "2001"},
                       kExitAlarm);
    EXPECT_EQ(refused["alarm"]["line"], 2);
    EXPECT_EQ(refused["alarm"]["column"], 5);
    EXPECT_NE(refused["alarm"]["message"].get<std::string>().find("offset memory A"), std::string::npos);
    EXPECT_EQ(refused["vars"]["2001"], 0.0) << "nothing written";

    json linuxCnc = run("lc.nc", "G10 L1 P1 Z50. R3.\nM30\n", {"--config", "machine", "--tools-out", "lc.tbl"});
    std::ifstream lc(dir_ / "lc.tbl");
    std::stringstream lcTable;
    lcTable << lc.rdbuf();
    EXPECT_NE(lcTable.str().find("T1 P1 Z50 D6 ;end mill"), std::string::npos) << lcTable.str();
}

TEST_F(CliToolDataTest, AnOffsetMemoryTheSimulatorHasNotIsRefusedAtItsPlace) {
    copyMachine("fanuc-0i");
    std::ifstream in(dir_ / "machine" / "machine.toml");
    std::stringstream toml;
    toml << in.rdbuf();
    std::string text = toml.str();
    ASSERT_NE(text.find("offset_memory = \"A\""), std::string::npos);
    text.replace(text.find("offset_memory = \"A\""), 19, "offset_memory = \"B\"");
    write("machine/machine.toml", text);
    write("p.nc", "M30\n");
    ProcessResult r = sim({"run", "p.nc", "--config", "machine"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_NE(r.err.find("machine.toml:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("offset_memory is \"A\" or \"C\""), std::string::npos) << r.err;
}

// The article's calibration program O9070, typed as the article prints it (its "09070" is the
// letter O), on the TS27R machine whose table does not know T97 yet: `#2297=336.489` is H97's
// geometry (offset memory C), which O9855 reads, so the stylus top comes out where the setter is.
TEST_F(CliToolDataTest, TheBreakageArticlesCalibrationProgramRunsAsWritten) {
    copyMachine("fanuc-ts27r");
    write("machine/tool.tbl", "T1 P1 Z120.0 D10.0 ;end mill D10\n");
    write("machine/O9070.nc",
          "%\n"
          "O9070\n"
          "M0\n"
          "G05.1Q0\n"
          "G90G80G40G49\n"
          "#2297=336.489\n"
          "G65P9855R10.016T97D12.7\n"
          "G05.1Q1\n"
          "M30\n"
          "%\n");
    std::ifstream in(dir_ / "machine" / "machine.toml");
    std::stringstream toml;
    toml << in.rdbuf();
    std::string text = toml.str();
    const std::string libraries = "other = [\"breakage.nc\"]";
    ASSERT_NE(text.find(libraries), std::string::npos);
    text.replace(text.find(libraries), libraries.size(), "other = [\"breakage.nc\", \"O9070.nc\"]");
    write("machine/machine.toml", text);
    // the operator's handwheel: the reference tool 10 mm above the stylus centre
    ProcessResult r = sim({"mdi", "G53 G00 X400. Y-50.", "G53 G00 Z-103.511", "M98 P9070", "--config", "machine",
                           "--tool", "97", "--print", "520,521,522,523,524,2297"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err << r.out;
    json j = output(r);
    EXPECT_NEAR(j["vars"]["2297"].get<double>(), 336.489, 1e-9);
    EXPECT_NEAR(j["vars"]["520"].get<double>(), -450.0, 1e-9) << "the stylus top";
    EXPECT_NEAR(j["vars"]["521"].get<double>(), 388.642, 1e-9);
    EXPECT_NEAR(j["vars"]["522"].get<double>(), 411.358, 1e-9);
    EXPECT_NEAR(j["vars"]["523"].get<double>(), -38.642, 1e-9);
    EXPECT_NEAR(j["vars"]["524"].get<double>(), -61.358, 1e-9);
}

// FANUC tool life settings are the control's parameters (fanuc-0i's params.toml, or --param):
// 6800 #0 GS1 / #1 GS2 as the 0i seed's table gives them (GS1 alone 64 x 4, GS2 alone 32 x 8),
// #2 LTM the kind of a group entered without Q, 6801 #6 EXT for G10 L3 P1 / P2, 6810 the ignore
// number. toollife.txt holds only the groups; a setting line there is refused at its place.
TEST_F(CliToolDataTest, FanucToolLifeSettingsAreTheControlsParameters) {
    copyMachine("fanuc-0i");
    std::string fiveTools = "G10 L3\nP1 L2\nT1\nT2\nT3\nT4\nT5\nG11\nM30\n";
    json gs1 = run("gs1.nc", fiveTools, {"--config", "machine", "--param", "6800=1"}, kExitAlarm);
    EXPECT_EQ(gs1["alarm"]["line"], 7);
    EXPECT_NE(gs1["alarm"]["message"].get<std::string>().find("at most 4 tools"), std::string::npos) << gs1["alarm"];
    json gs2 = run("gs2.nc", "G10 L3\nP33 L2\nT1\nG11\nM30\n", {"--config", "machine", "--param", "6800=2"},
                   kExitAlarm);
    EXPECT_EQ(gs2["alarm"]["line"], 2);
    EXPECT_NE(gs2["alarm"]["message"].get<std::string>().find("32 groups"), std::string::npos) << gs2["alarm"];
    run("eight.nc", "G10 L3\nP32 L2\nT1\nT2\nT3\nT4\nT5\nT6\nT7\nT8\nG11\nM30\n",
        {"--config", "machine", "--param", "6800=2"});

    json ltm = run("ltm.nc", "G10 L3\nP1 L2\nT11\nG11\nM30\n", {"--config", "machine", "--param", "6800=4"});
    EXPECT_EQ(ltm["tool_life"]["groups"][0]["kind"], "minutes") << "LTM = 1: no Q is minutes";
    EXPECT_EQ(ltm["tool_life"]["gs"], 0);

    json noExt = run("p1.nc", "G10 L3 P1\nP2 L3\nT21\nG11\nM30\n", {"--config", "machine", "--param", "6801=0"},
                     kExitAlarm);
    EXPECT_EQ(noExt["alarm"]["line"], 1);
    EXPECT_NE(noExt["alarm"]["message"].get<std::string>().find("6801 #6 EXT"), std::string::npos);
    json ext = run("p1ok.nc", "G10 L3 P1\nP2 L3\nT21\nG11\nM30\n", {"--config", "machine"});
    EXPECT_EQ(ext["tool_life"]["groups"].size(), 2u) << "params.toml's 6801 = 64: P1 adds group 2";

    json ignore = run("t51.nc", "T51 M6\nM30\n", {"--config", "machine", "--param", "6810=50"});
    EXPECT_EQ(ignore["tool"], 11) << "6810 = 50: T51 is group 1";
    EXPECT_EQ(ignore["tool_life"]["ignore"], 50);

    std::ifstream in(dir_ / "machine" / "toollife.txt");
    std::stringstream life;
    life << in.rdbuf();
    EXPECT_EQ(life.str().find("\ngs "), std::string::npos) << "the settings are not the file's:\n" << life.str();
    write("machine/toollife.txt", life.str() + "ignore 200\n");
    json refused = run("any.nc", "M30\n", {"--config", "machine"});
    ASSERT_EQ(refused["tool_life"]["issues"].size(), 1u) << refused["tool_life"];
    EXPECT_NE(refused["tool_life"]["issues"][0]["message"].get<std::string>().find("parameter 6810"),
              std::string::npos);
    EXPECT_EQ(refused["tool_life"]["issues"][0]["column"], 1);
    EXPECT_EQ(refused["tool_life"]["ignore"], 100);

    ProcessResult bad = sim({"run", "any.nc", "--config", "machine", "--param", "6800=1.5"});
    EXPECT_EQ(bad.exitStatus, kExitUsage) << bad.err;
    EXPECT_NE(bad.err.find("6800 must be a whole number from 0 to 255"), std::string::npos) << bad.err;
}

// With every tool of a group spent the control goes on with the group's last tool and raises the
// tool change signal TLCH; the new tool signal TLNW marks the T that moved on to a sister tool.
// The PMC hands both to macros as #1003 and #1004.
TEST_F(CliToolDataTest, AnExpiredGroupGoesOnWithItsLastToolAndRaisesTheToolChangeSignal) {
    copyMachine("fanuc-0i");
    run("enter.nc", "G10 L3\nP1 L1 Q1\nT11 H11 D31\nT12 H12 D32\nG11\nM30\n", {"--config", "machine"});
    const std::string program = "T101 M6\n#100 = #1003\n#101 = #1004\nM30\n";
    json first = run("use.nc", program, {"--config", "machine", "--print", "100,101"});
    EXPECT_EQ(first["tool"], 11);
    EXPECT_EQ(first["vars"]["100"], 0.0);
    EXPECT_EQ(first["vars"]["101"], 0.0);
    json second = run("use.nc", program, {"--config", "machine", "--print", "100,101"});
    EXPECT_EQ(second["tool"], 12);
    EXPECT_EQ(second["vars"]["101"], 1.0) << "TLNW: T12 took over from T11";
    EXPECT_EQ(second["vars"]["100"], 1.0) << "TLCH: T12's only use spent the group";
    json spent = run("use.nc", program, {"--config", "machine", "--print", "100,101"});
    EXPECT_EQ(spent["status"], "ok") << "no alarm: the last tool goes on";
    EXPECT_EQ(spent["tool"], 12);
    EXPECT_EQ(spent["vars"]["100"], 1.0);
    EXPECT_EQ(spent["vars"]["101"], 0.0);
    EXPECT_EQ(spent["tool_life"]["tool_change_signal"], true);
    EXPECT_EQ(spent["tool_life"]["groups"][0]["tools"][1]["used"], 2) << "its uses go on being counted";
    ASSERT_FALSE(spent["messages"].empty());
    EXPECT_NE(spent["messages"][0].get<std::string>().find("every tool of group 1 has reached its life"),
              std::string::npos)
        << spent["messages"];
}

// LinuxCNC's random tool changer ([EMCIO]RANDOM_TOOLCHANGER = 1, here machine.toml's [tool_data]
// random_changer = true): at M6 the new tool leaves its pocket for the spindle (pocket 0) and the
// old one takes that pocket, so the table's P column follows the tools. rs274 leaves the pockets
// to iocontrol (its table is not rewritten), so the pockets are checked against the seed's rule.
TEST_F(CliToolDataTest, TheRandomChangerSwapsPocketsAtEachChange) {
    copyMachine("fanuc-ts27r");
    write("machine/tool.tbl", "T1 P0 Z120.0 D10.0 ;in the spindle\nT2 P2 Z95.5\nT3 P3 Z150.25\n");
    std::ifstream in(dir_ / "machine" / "machine.toml");
    std::stringstream toml;
    toml << in.rdbuf();
    write("machine/machine.toml", toml.str() + "random_changer = true\n");
    json j = run("swap.nc", "T2 M6\nT3 M6\nG43 H3 G0 Z0\nM30\n",
                 {"--config", "machine", "--tool", "1", "--tools-out", "out.tbl"});
    EXPECT_EQ(j["tool"], 3);
    EXPECT_NEAR(j["machine"]["Z"].get<double>(), 150.25, 1e-9);
    std::ifstream out(dir_ / "out.tbl");
    std::stringstream table;
    table << out.rdbuf();
    EXPECT_EQ(table.str(), "T1 P2 Z120 D10 ;in the spindle\nT2 P3 Z95.5\nT3 P0 Z150.25\n") << table.str();

    json fixed = run("fixed.nc", "T2 M6\nM30\n",
                     {"--config", bundled("fanuc-ts27r"), "--tool", "1", "--tools-out", "fixed.tbl"});
    std::ifstream f(dir_ / "fixed.tbl");
    std::stringstream fixedTable;
    fixedTable << f.rdbuf();
    EXPECT_NE(fixedTable.str().find("T1 P1 Z120.0"), std::string::npos) << "a fixed-pocket changer keeps P";
}

// G10 L0, M61 and G43.1 where they cannot mean what LinuxCNC means: refused at their word.
TEST_F(CliToolDataTest, LinuxCncToolCodesAreRefusedWhereTheyHaveNoMeaning) {
    json noTable = run("m61.nc", "M61 Q3\nM30\n", {"--config", bundled("fanuc-0i")}, kExitAlarm);
    EXPECT_EQ(noTable["alarm"]["column"], 1);
    EXPECT_NE(noTable["alarm"]["message"].get<std::string>().find("keeps a tool table"), std::string::npos);
    json g431 = run("g431.nc", "G43.1 Z5.\nM30\n", {"--config", bundled("fanuc-0i")}, kExitAlarm);
    EXPECT_NE(g431["alarm"]["message"].get<std::string>().find("G43.1"), std::string::npos);

    json loaded = run("l0.nc", "G10 L0\nM30\n", {"--config", bundled("fanuc-ts27r"), "--tool", "2"}, kExitAlarm);
    EXPECT_NE(loaded["alarm"]["message"].get<std::string>().find("not allowed with a tool loaded (T2)"),
              std::string::npos)
        << loaded["alarm"];
    json unloaded = run("l0ok.nc", "M61 Q0\nG10 L0\n#100 = #2202\nM30\n",
                        {"--config", bundled("fanuc-ts27r"), "--tool", "2", "--print", "100"});
    EXPECT_EQ(unloaded["tool"], 0) << "M61 Q0: nothing in the spindle, no change made";
    EXPECT_EQ(unloaded["vars"]["100"], 95.5);

    json xWord = run("x.nc", "G43.1 X1. Z5.\nM30\n", {"--config", bundled("fanuc-ts27r")}, kExitAlarm);
    EXPECT_EQ(xWord["alarm"]["column"], 7);

    json carousel = run("um.nc", "M61 Q3\nM30\n", {"--config", bundled("fanuc-umbrella"), "--tool", "4"}, kExitAlarm);
    EXPECT_NE(carousel["alarm"]["message"].get<std::string>().find("magazine knows"), std::string::npos);
    EXPECT_EQ(carousel["tool"], 4);

    json m350 = run("m350.nc", "M61 Q3\nM30\n", {}, kExitAlarm);
    EXPECT_EQ(m350["alarm"]["line"], 1);
}

} // namespace m350::clitest
