// FANUC's coordinate options through m350-sim check and run: G54.1 P1-Pn with G10 L20 and their
// variables, G68 / G69, and the common variables a machine folder declares (machine.toml
// [variables] common, [coordinates]); the M350 dialect refuses them at their line and column.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace m350::clitest {

namespace {

const char* const kCoordinates = "G90 G10 L20 P3 X100. Y50. Z-10.\n"
                                 "G54.1 P3\n"
                                 "G00 X0 Y0 Z0\n"
                                 "#100 = #7041\n"
                                 "G68 X10. Y0 R90.\n"
                                 "G01 X20. Y0 F500.\n"
                                 "G69\n"
                                 "M30\n";

class CoordinatesTest : public CliTest {
  protected:
    std::string machine(const std::string& name) const { return std::string(M350_MACHINES_DIR) + "/" + name; }

    fs::path copyMachine(const std::string& name) {
        fs::path copy = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / name, copy, fs::copy_options::recursive);
        return copy;
    }

    // check's findings as "line:column: message"
    static std::vector<std::string> findings(const json& j) {
        std::vector<std::string> out;
        for (const json& d : j["diagnostics"]) {
            out.push_back(std::to_string(d.value("line", 0)) + ":" + std::to_string(d.value("column", 0)) + ": " +
                          d.value("message", ""));
        }
        return out;
    }
};

} // namespace

TEST_F(CoordinatesTest, AFanucMachineChecksAndRunsThem) {
    write("c.nc", kCoordinates);
    for (const char* folder : {"fanuc-0i", "fanuc-30i"}) {
        ProcessResult check = sim({"check", "c.nc", "--config", machine(folder)});
        EXPECT_EQ(check.exitStatus, kExitOk) << folder << check.err;
        EXPECT_TRUE(output(check)["diagnostics"].empty()) << folder << check.out;

        ProcessResult run = sim({"run", "c.nc", "--config", machine(folder), "--print", "100,4016"});
        EXPECT_EQ(run.exitStatus, kExitOk) << folder << run.err;
        json j = output(run);
        expectRunContract(j);
        EXPECT_EQ(j["vars"]["100"], 100.0) << folder;
        EXPECT_EQ(j["vars"]["4016"], 69.0) << folder;
        // X20 Y0 turned by 90 about X10 Y0 is X10 Y10, in G54.1 P3 (X100 Y50)
        EXPECT_NEAR(j["machine"].value("X", 0.0), 110.0, 1e-9) << folder;
        EXPECT_NEAR(j["machine"].value("Y", 0.0), 60.0, 1e-9) << folder;
        EXPECT_NEAR(j["work"].value("X", 0.0), 10.0, 1e-9) << folder; // the DRO is not turned
        EXPECT_NEAR(j["work"].value("Y", 0.0), 10.0, 1e-9) << folder;
    }
}

TEST_F(CoordinatesTest, TheM350RefusesThemAtTheirPlace) {
    write("c.nc", kCoordinates);
    ProcessResult check = sim({"check", "c.nc"});
    EXPECT_EQ(check.exitStatus, kExitError) << check.err;
    EXPECT_EQ(findings(output(check)),
              (std::vector<std::string>{"2:1: G54.1: not a G code this machine knows",
                                        "4:8: #7041 does not exist in the m350 dialect",
                                        "5:1: G68: not a G code this machine knows",
                                        "7:1: G69: not a G code this machine knows"}));
    EXPECT_NE(check.err.find("c.nc:2:1: G54.1: not a G code this machine knows"), std::string::npos) << check.err;

    write("l20.nc", "G10 L20 P1 X0\nM30\n");
    ProcessResult run = sim({"run", "l20.nc"});
    EXPECT_EQ(run.exitStatus, kExitAlarm) << run.err;
    json alarm = output(run)["alarm"];
    EXPECT_EQ(alarm.value("line", 0), 1);
    EXPECT_EQ(alarm.value("column", 0), 1);
    EXPECT_NE(alarm.value("message", "").find("not available on the M350"), std::string::npos) << alarm;

    write("g68.nc", "G00 X0\nG68 X0 Y0 R30\nM30\n");
    ProcessResult g68 = sim({"run", "g68.nc"});
    EXPECT_EQ(g68.exitStatus, kExitAlarm) << g68.err;
    EXPECT_NE(g68.err.find("g68.nc:2:1: alarm: G68: not a G code this machine knows"), std::string::npos) << g68.err;
}

TEST_F(CoordinatesTest, A0iHas48SystemsAndItsOwnCommonVariables) {
    write("c.nc", "G54.1 P48\nG54.1 P49\n#300 = 1\n#7960 = 1\nM30\n");
    ProcessResult check = sim({"check", "c.nc", "--config", machine("fanuc-0i")});
    EXPECT_EQ(check.exitStatus, kExitError) << check.err;
    EXPECT_EQ(findings(output(check)),
              (std::vector<std::string>{
                  "2:7: P49: G54.1 selects the additional work systems P1-P48 of this machine (machine.toml "
                  "[coordinates] additional_systems)",
                  "3:1: #300 does not exist in the fanuc dialect (this machine's common variables are #100-#199, "
                  "#500-#999: machine.toml [variables] common)",
                  "4:1: #7960 does not exist in the fanuc dialect"}));
    ProcessResult run = sim({"run", "c.nc", "--config", machine("fanuc-0i")});
    EXPECT_EQ(run.exitStatus, kExitAlarm) << run.err;
    EXPECT_NE(run.err.find("c.nc:2:7: alarm: P49: G54.1 selects"), std::string::npos) << run.err;
}

TEST_F(CoordinatesTest, The30iHas300SystemsAndTheAddedCommonVariables) {
    write("c.nc", "G10 L20 P300 X1. Y2.\nG54.1 P300\n#300 = #19982\n#98000 = #14001 + 3\n#98499 = 7\nM30\n");
    ProcessResult check = sim({"check", "c.nc", "--config", machine("fanuc-30i")});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult run = sim({"run", "c.nc", "--config", machine("fanuc-30i"), "--print", "300,98000,98499,4130"});
    EXPECT_EQ(run.exitStatus, kExitOk) << run.err;
    json vars = output(run)["vars"];
    EXPECT_EQ(vars["300"], 2.0);
    EXPECT_EQ(vars["98000"], 3.0);
    EXPECT_EQ(vars["98499"], 7.0);
    EXPECT_EQ(vars["4130"], 300.0);

    write("beyond.nc", "#1 = 0\n#98500 = 1\nG54.1 P301\nM30\n");
    ProcessResult beyond = sim({"check", "beyond.nc", "--config", machine("fanuc-30i")});
    EXPECT_EQ(beyond.exitStatus, kExitError) << beyond.err;
    EXPECT_EQ(findings(output(beyond)),
              (std::vector<std::string>{
                  "2:1: #98500 does not exist in the fanuc dialect (this machine's common variables are #100-#499, "
                  "#500-#999, #98000-#98499: machine.toml [variables] common)",
                  "3:7: P301: G54.1 selects the additional work systems P1-P300 of this machine (machine.toml "
                  "[coordinates] additional_systems)"}));
}

// Retained variables (#500 on) load from variables.toml as #500-#999 always have; a number the
// machine lacks is said and skipped.
TEST_F(CoordinatesTest, DeclaredRetainedVariablesLoadFromVariablesToml) {
    fs::path folder = copyMachine("fanuc-30i");
    std::ofstream(folder / "variables.toml") << "[variables]\n98000 = 12.5\n700 = 1\n98500 = 3\n";
    write("c.nc", "#1 = #98000\nM30\n");
    ProcessResult run = sim({"run", "c.nc", "--config", "machine", "--print", "98000,700"});
    EXPECT_EQ(run.exitStatus, kExitOk) << run.err;
    json vars = output(run)["vars"];
    EXPECT_EQ(vars["98000"], 12.5);
    EXPECT_EQ(vars["700"], 1.0);
    EXPECT_NE(run.err.find("machine/variables.toml:4:1: warning: #98500 is no variable of this machine"),
              std::string::npos)
        << run.err;

    ProcessResult option = sim({"run", "c.nc", "--config", "machine", "--var", "98000=4", "--print", "98000"});
    EXPECT_EQ(option.exitStatus, kExitOk) << option.err;
    EXPECT_EQ(output(option)["vars"]["98000"], 4.0);
    ProcessResult missing = sim({"run", "c.nc", "--config", machine("fanuc-0i"), "--var", "98000=4"});
    EXPECT_EQ(missing.exitStatus, kExitUsage) << missing.err;
}

TEST_F(CoordinatesTest, MachineTomlOptionsAreCheckedWhereTheyStand) {
    struct Case {
        const char* folder;
        const char* append; // a table and its key, on the two lines after a blank one
        int column;         // of the value refused, on the key's line
        const char* says;
    };
    for (const Case& c :
         {Case{"fanuc-0i", "[variables]\ncommon = [\"100-1500\"]\n", 11, "#100-#1500 is not a common variable range"},
          Case{"fanuc-0i", "[variables]\ncommon = [\"100-499\", \"400-600\"]\n", 22, "overlap"},
          Case{"fanuc-0i", "[variables]\ncommon = [\"lots\"]\n", 11, "each range is a string such as"},
          Case{"fanuc-0i", "[coordinates]\nadditional_systems = 301\n", 22, "from 0 to 300"},
          Case{"fanuc-0i", "[coordinates]\nrotation = 1\n", 12, "true or false"},
          Case{"m350-linear16", "[coordinates]\nrotation = true\n", 0, "the M350 has neither G54.1 nor G68"},
          Case{"m350-linear16", "[variables]\ncommon = [\"100-199\"]\n", 10, "the M350's variables are fixed"}}) {
        fs::remove_all(dir_ / "machine");
        fs::path folder = copyMachine(c.folder);
        std::string text;
        {
            std::ifstream in(folder / "machine.toml", std::ios::binary);
            text.assign(std::istreambuf_iterator<char>(in), {});
        }
        ASSERT_EQ(text.back(), '\n');
        const auto lineCount = std::count(text.begin(), text.end(), '\n');
        std::ofstream(folder / "machine.toml", std::ios::binary) << text << "\n" << c.append;
        const std::string where = c.column > 0 ? ":" + std::to_string(lineCount + 3) + ":" + std::to_string(c.column)
                                               : ":" + std::to_string(lineCount + 2) + ":1";
        ProcessResult r = sim({"mdi", "G0 X1", "--config", "machine"});
        EXPECT_EQ(r.exitStatus, kExitError) << c.append << r.err;
        EXPECT_NE(r.err.find("machine/machine.toml" + where), std::string::npos) << c.append << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.append << r.err;
    }
}

} // namespace m350::clitest
