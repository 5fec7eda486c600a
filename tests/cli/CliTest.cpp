// CLI tests: m350-sim run as a user (or a grader's script) runs it, checking the contract of
// README.md "m350-sim": exit status, exactly one JSON object on stdout, `file:line:col: message`
// on stderr, and what each option does.
#include "tests/cli/SimProcess.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using m350::testing::ProcessResult;
using nlohmann::json;

constexpr int kExitOk = 0;
constexpr int kExitAlarm = 1;
constexpr int kExitError = 2;
constexpr int kExitUsage = 64;
constexpr std::size_t kOutputCount = 21; // OUT01..OUT21

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty()) {
            out.push_back(line);
        }
    }
    return out;
}

std::set<std::string> keysOf(const json& object) {
    std::set<std::string> keys;
    for (const auto& [key, value] : object.items()) {
        keys.insert(key);
    }
    return keys;
}

bool allDigits(const std::string& s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

// Every run and mdi output: the keys README.md lists, each of its type.
void expectRunContract(const json& j) {
    ASSERT_TRUE(j.is_object());
    const std::set<std::string> contract{"status",  "alarm",   "vars",     "machine",    "work",       "tool",
                                         "pockets", "outputs", "messages", "sim_time_s", "diagnostics"};
    EXPECT_EQ(keysOf(j), contract);

    ASSERT_TRUE(j.contains("status") && j["status"].is_string());
    const std::string status = j["status"];
    EXPECT_TRUE(status == "ok" || status == "alarm" || status == "error") << status;

    if (j.contains("alarm") && !j["alarm"].is_null()) {
        const json& a = j["alarm"];
        ASSERT_TRUE(a.is_object()) << a;
        EXPECT_EQ(keysOf(a), (std::set<std::string>{"code", "message", "file", "line", "column"}));
        EXPECT_TRUE(a.value("code", json()).is_string()) << a;
        EXPECT_TRUE(a.value("message", json()).is_string()) << a;
        EXPECT_TRUE(a.value("file", json()).is_string()) << a;
        EXPECT_TRUE(a.value("line", json()).is_number_integer()) << a;
        EXPECT_TRUE(a.value("column", json()).is_number_integer()) << a;
    }
    EXPECT_EQ(j.value("alarm", json()).is_null(), status == "ok")
        << "alarm must be null exactly when status is ok";

    if (j.contains("vars")) {
        ASSERT_TRUE(j["vars"].is_object());
        for (const auto& [n, v] : j["vars"].items()) {
            EXPECT_TRUE(allDigits(n)) << n;
            EXPECT_TRUE(v.is_number() || v.is_null()) << n << ": " << v;
        }
    }
    for (const char* frame : {"machine", "work"}) {
        if (!j.contains(frame)) {
            continue;
        }
        EXPECT_EQ(keysOf(j[frame]), (std::set<std::string>{"X", "Y", "Z", "A", "B"})) << frame;
        for (const auto& [axis, v] : j[frame].items()) {
            EXPECT_TRUE(v.is_number()) << frame << "." << axis << ": " << v;
        }
    }
    if (j.contains("tool")) {
        EXPECT_TRUE(j["tool"].is_number_integer()) << j["tool"];
    }
    if (j.contains("pockets")) {
        ASSERT_TRUE(j["pockets"].is_object());
        for (const auto& [pocket, tool] : j["pockets"].items()) {
            EXPECT_TRUE(allDigits(pocket)) << pocket;
            EXPECT_TRUE(tool.is_number_integer() && tool.get<int>() >= 0) << pocket << ": " << tool;
        }
    }
    if (j.contains("outputs")) {
        ASSERT_TRUE(j["outputs"].is_array());
        EXPECT_EQ(j["outputs"].size(), kOutputCount);
        for (const json& level : j["outputs"]) {
            EXPECT_TRUE(level == 0 || level == 1) << level;
        }
    }
    if (j.contains("messages")) {
        ASSERT_TRUE(j["messages"].is_array());
        for (const json& m : j["messages"]) {
            EXPECT_TRUE(m.is_string()) << m;
        }
    }
    if (j.contains("sim_time_s")) {
        EXPECT_TRUE(j["sim_time_s"].is_number() && j["sim_time_s"].get<double>() >= 0) << j["sim_time_s"];
    }
    if (j.contains("diagnostics")) {
        ASSERT_TRUE(j["diagnostics"].is_array());
        for (const json& d : j["diagnostics"]) {
            EXPECT_EQ(keysOf(d),
                      (std::set<std::string>{"file", "line", "column", "severity", "kind", "message"}))
                << d;
        }
    }
}

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "m350-cli-XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    fs::path write(const std::string& name, const std::string& text) {
        fs::path path = dir_ / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    // Runs m350-sim in the test's scratch folder.
    ProcessResult sim(const std::vector<std::string>& args) {
        return m350::testing::runProcess(M350_SIM_PATH, args, dir_.string());
    }

    // Stdout must hold exactly one JSON object; returns it.
    static json output(const ProcessResult& r) {
        json j;
        try {
            j = json::parse(r.out);
        } catch (const json::exception& e) {
            ADD_FAILURE() << "stdout is not one JSON document (" << e.what() << "):\n"
                          << r.out << "\nstderr:\n"
                          << r.err;
            return json::object();
        }
        EXPECT_TRUE(j.is_object()) << r.out;
        EXPECT_EQ(lines(r.out).size(), 1u) << "one JSON object on one line:\n" << r.out;
        return j;
    }

    // Writes `text` to `file` and runs it; the exit status and "status" must be the given pair.
    json runExpecting(const std::string& file, const char* text, int exitStatus, const std::string& status) {
        write(file, text);
        ProcessResult r = sim({"run", file});
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err;
        json j = output(r);
        EXPECT_EQ(j.value("status", ""), status) << r.out;
        return j;
    }

    fs::path dir_;
};

const char* const kEndingProgram = "G00 X1 Y2\nM30\n";
const char* const kAlarmProgram = "#1=0\n#2=1/#1\nM30\n";
const char* const kSyntaxErrorProgram = "G00 X1\n#1=[2\nM30\n";

TEST_F(CliTest, ExitStatusIsZeroWhenTheProgramEnds) {
    runExpecting("ok.nc", kEndingProgram, kExitOk, "ok");
}

TEST_F(CliTest, ExitStatusIsOneOnAnAlarm) {
    json j = runExpecting("alarm.nc", kAlarmProgram, kExitAlarm, "alarm");
    EXPECT_EQ(j["alarm"].value("code", ""), "division_by_zero");
}

TEST_F(CliTest, ExitStatusIsTwoOnASyntaxError) {
    json j = runExpecting("bad.nc", kSyntaxErrorProgram, kExitError, "error");
    ASSERT_TRUE(j["alarm"].is_object()) << j;
    EXPECT_EQ(j["alarm"].value("file", ""), "bad.nc");
    EXPECT_EQ(j["alarm"].value("line", 0), 2);
}

TEST_F(CliTest, UsageErrorsExitWith64) {
    write("ok.nc", kEndingProgram);
    const std::vector<std::vector<std::string>> usages = {
        {},                                       // no command
        {"frobnicate"},                           // unknown command
        {"run"},                                  // missing PROGRAM
        {"check"},                                // missing PROGRAM
        {"mdi"},                                  // no lines
        {"run", "ok.nc", "--bogus"},              // unknown option
        {"run", "ok.nc", "--param", "5"},         // not N=V
        {"run", "ok.nc", "--param", "x=1"},       // N not a number
        {"run", "ok.nc", "--param", "61=fast"},   // V not a number
        {"run", "ok.nc", "--param", "1000=1"},    // parameters are 0-999
        {"run", "ok.nc", "--var", "100"},         // not N=V
        {"run", "ok.nc", "--input", "IN99=1"},    // inputs are IN01-IN24
        {"run", "ok.nc", "--input", "IN11=2"},    // levels are 0 and 1
        {"run", "ok.nc", "--input", "OUT01=1"},   // not an input
        {"run", "ok.nc", "--dialect", "klingon"}, // m350 or fanuc
        {"run", "ok.nc", "--max-sim-time", "0"},  // must be positive
        {"run", "ok.nc", "--print", "1,x"},       // variable numbers
        {"run", "ok.nc", "--tool", "two"},        // a whole number
    };
    for (const auto& args : usages) {
        std::string shown;
        for (const std::string& a : args) {
            shown += " " + a;
        }
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitUsage)
            << "m350-sim" << shown << "\nstdout: " << r.out << "\nstderr: " << r.err;
        EXPECT_FALSE(r.err.empty()) << "a usage error says why on stderr: m350-sim" << shown;
    }
}

TEST_F(CliTest, HelpExitsZero) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"run", "--help"}}) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
        for (const char* word : {"run", "mdi", "check"}) {
            if (args.size() == 1) {
                EXPECT_NE(r.out.find(word), std::string::npos) << "--help names the command " << word << ":\n"
                                                               << r.out;
            }
        }
        EXPECT_NE(r.out.find("--"), std::string::npos) << "help lists options:\n" << r.out;
    }
}

TEST_F(CliTest, StdoutIsOneJsonObjectWithTheContractKeys) {
    write("ok.nc", kEndingProgram);
    write("alarm.nc", kAlarmProgram);
    write("bad.nc", kSyntaxErrorProgram);
    write("tool.nc", "T2\nM30\n");
    const std::vector<std::vector<std::string>> runs = {
        {"run", "ok.nc"},
        {"run", "alarm.nc", "--print", "1,2"},
        {"run", "bad.nc"},
        {"run", "tool.nc", "--trace", "t.jsonl"},
        {"run", "ok.nc", "--dialect", "fanuc", "--print", "1"},
        {"mdi", "G00 X3", "#100=#880", "--print", "100"},
    };
    for (const auto& args : runs) {
        SCOPED_TRACE(args[0] + " " + args[1]);
        ProcessResult r = sim(args);
        expectRunContract(output(r));
    }
}

TEST_F(CliTest, CheckPrintsStatusAndDiagnosticsOnly) {
    write("ok.nc", kEndingProgram);
    write("bad.nc", kSyntaxErrorProgram);
    for (const char* file : {"ok.nc", "bad.nc"}) {
        ProcessResult r = sim({"check", file});
        json j = output(r);
        EXPECT_EQ(keysOf(j), (std::set<std::string>{"status", "diagnostics"})) << j;
    }
}

TEST_F(CliTest, CheckOfACleanFileIsOk) {
    write("ok.nc", "#1=2\nWHILE [#1 GT 0] DO1\n#1=#1-1\nEND1\nG01 X#1 F100\nM30\n");
    ProcessResult r = sim({"check", "ok.nc"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "ok");
    EXPECT_EQ(j.value("diagnostics", json()), json::array());
    EXPECT_EQ(r.err, "");
}

TEST_F(CliTest, CheckListsEveryErrorOfTheFile) {
    write("three.nc", "#1=1\n"
                      "#2=[#1+1\n" // line 2: ']' missing
                      "G00 X1\n"
                      "G01 X#1+2 F100\n" // line 4: arithmetic without brackets
                      "#3=#1\n"
                      "#1552+#20-1] = 1\n" // line 6: the manual's damaged release line
                      "M30\n");
    ProcessResult r = sim({"check", "three.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "error");
    ASSERT_TRUE(j["diagnostics"].is_array());
    std::vector<int> errorLines;
    for (const json& d : j["diagnostics"]) {
        EXPECT_EQ(d.value("file", ""), "three.nc");
        EXPECT_EQ(d.value("severity", ""), "error");
        EXPECT_EQ(d.value("kind", ""), "syntax");
        EXPECT_GT(d.value("column", 0), 0) << d;
        errorLines.push_back(d.value("line", 0));
    }
    EXPECT_EQ(errorLines, (std::vector<int>{2, 4, 6}));
    std::vector<std::string> stderrLines = lines(r.err);
    ASSERT_EQ(stderrLines.size(), 3u) << r.err;
    EXPECT_EQ(stderrLines[0].rfind("three.nc:2:", 0), 0u) << stderrLines[0];
    EXPECT_EQ(stderrLines[1].rfind("three.nc:4:", 0), 0u) << stderrLines[1];
    EXPECT_EQ(stderrLines[2].rfind("three.nc:6:12: ", 0), 0u) << stderrLines[2];
}

TEST_F(CliTest, StderrNamesFileLineAndColumn) {
    const std::regex located(R"(^[^:]+:\d+:\d+: .+)");
    write("bad.nc", kSyntaxErrorProgram);
    write("alarm.nc", kAlarmProgram);
    for (const auto& args :
         {std::vector<std::string>{"check", "bad.nc"}, {"run", "bad.nc"}, {"run", "alarm.nc"}}) {
        ProcessResult r = sim(args);
        std::vector<std::string> errLines = lines(r.err);
        ASSERT_FALSE(errLines.empty()) << args[0] << " " << args[1];
        for (const std::string& line : errLines) {
            EXPECT_TRUE(std::regex_match(line, located)) << line;
        }
    }
    ProcessResult alarm = sim({"run", "alarm.nc"});
    EXPECT_NE(alarm.err.find("alarm.nc:2:5: "), std::string::npos) << alarm.err; // the '/' of #2=1/#1
}

TEST_F(CliTest, MissingProgramFileIsAnError) {
    for (const char* command : {"run", "check"}) {
        ProcessResult r = sim({command, "no-such-program.nc"});
        EXPECT_EQ(r.exitStatus, kExitError) << command;
        json j = output(r);
        EXPECT_EQ(j.value("status", ""), "error") << command;
        EXPECT_NE(r.err.find("no-such-program.nc"), std::string::npos) << r.err;
    }
}

TEST_F(CliTest, BadMachineFolderIsAnError) {
    write("ok.nc", kEndingProgram);
    write("klingon/machine.toml", "name = \"x\"\ndialect = \"klingon\"\n");
    write("broken/machine.toml", "name = \"x\"\ndialect = \"m350\"\n");
    write("broken/params.toml", "[params]\n61 = \"fast\"\n");
    write("nolib/machine.toml", "dialect = \"m350\"\n[libraries]\ng = \"missing.nc\"\n");
    for (const char* folder : {"no-such-folder", "klingon", "broken", "nolib"}) {
        ProcessResult r = sim({"run", "ok.nc", "--config", folder});
        EXPECT_EQ(r.exitStatus, kExitError) << folder << ": " << r.out;
        EXPECT_EQ(output(r).value("status", ""), "error") << folder;
        EXPECT_FALSE(r.err.empty()) << folder;
    }
}

// README: run and mdi print one object with the contract's keys, errors included.
TEST_F(CliTest, ErrorsFoundBeforeTheRunKeepTheContractShape) {
    write("ok.nc", kEndingProgram);
    {
        SCOPED_TRACE("missing program file");
        expectRunContract(output(sim({"run", "no-such-program.nc"})));
    }
    {
        SCOPED_TRACE("missing machine folder");
        expectRunContract(output(sim({"run", "ok.nc", "--config", "no-such-folder"})));
    }
}

TEST_F(CliTest, UnwritableTraceFileIsAnError) {
    write("ok.nc", kEndingProgram);
    ProcessResult r = sim({"run", "ok.nc", "--trace", "no-such-folder/trace.jsonl"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_EQ(output(r).value("status", ""), "error");
}

TEST_F(CliTest, PrintReportsExactlyTheListedVariables) {
    write("ok.nc", "#100=2.5\nM30\n");
    ProcessResult r = sim({"run", "ok.nc", "--print", "1,100,1300"});
    json vars = output(r).value("vars", json());
    EXPECT_EQ(keysOf(vars), (std::set<std::string>{"1", "100", "1300"}));
    EXPECT_EQ(vars.value("1", json()), 0); // M350 locals start at 0
    EXPECT_EQ(vars.value("100", json()), 2.5);
    EXPECT_EQ(vars.value("1300", json()), 1); // param 800 of the default machine: tool 1

    ProcessResult none = sim({"run", "ok.nc"});
    EXPECT_EQ(output(none).value("vars", json()), json::object());
}

TEST_F(CliTest, VacantPrintsAsNull) {
    write("vacant.nc", "#101=3\n#102=#100\nM30\n");
    ProcessResult r = sim({"run", "vacant.nc", "--dialect", "fanuc", "--print", "100,101,102,0"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json vars = output(r).value("vars", json());
    EXPECT_TRUE(vars.value("100", json(1)).is_null()) << vars;
    EXPECT_EQ(vars.value("101", json()), 3);
    EXPECT_TRUE(vars.value("102", json(1)).is_null()) << vars;
    EXPECT_TRUE(vars.value("0", json(1)).is_null()) << vars;
}

TEST_F(CliTest, VarAndParamSetValuesBeforeTheRun) {
    write("copy.nc", "#101=#100\n#102=#561\nM30\n");
    ProcessResult r = sim({"run", "copy.nc", "--var", "100=7.5", "--param", "61=1234", "--param", "801=4",
                           "--print", "101,102,1301"});
    json j = output(r);
    EXPECT_EQ(j["vars"].value("101", json()), 7.5);
    EXPECT_EQ(j["vars"].value("102", json()), 1234);
    EXPECT_EQ(j["vars"].value("1301", json()), 4);
    EXPECT_EQ(keysOf(j.value("pockets", json::object())), (std::set<std::string>{"1", "2", "3", "4"}));
}

TEST_F(CliTest, MdiRunsTheLinesInOrder) {
    ProcessResult r =
        sim({"mdi", "#100=1", "#100=#100*10", "#100=#100+2", "G00 X5", "G00 X7", "--print", "100"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"].value("100", json()), 12); // (1 * 10) + 2; any other order gives another number
    EXPECT_EQ(j["work"].value("X", json()), 7);
}

TEST_F(CliTest, StartOptionsSetTheMachineUp) {
    write("probe.nc", "#100=#1526\nM30\n"); // #1526 = IN07
    json j = output(sim({"run", "probe.nc", "--tool", "3", "--unhomed", "--input", "IN07=1", "--print",
                         "100,1300,1515,1516,1517"}));
    EXPECT_EQ(j.value("tool", -1), 3);
    EXPECT_EQ(j["pockets"].value("3", -1), 0);
    EXPECT_EQ(j["vars"], (json{{"100", 1}, {"1300", 3}, {"1515", 0}, {"1516", 0}, {"1517", 0}}));
}

TEST_F(CliTest, MaxSimTimeStopsARunawayLoop) {
    write("loop.nc", "N1 G04 P1000\nGOTO1\n");
    ProcessResult r = sim({"run", "loop.nc", "--max-sim-time", "3"});
    EXPECT_EQ(r.exitStatus, kExitAlarm);
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit");
    double t = j.value("sim_time_s", 0.0);
    EXPECT_GT(t, 3.0);
    EXPECT_LT(t, 4.1);
}

TEST_F(CliTest, TraceWritesJsonLinesWithMoves) {
    write("moves.nc", "G00 X10 Y20\nG01 Z-5 F600\nT2\nG00 X0 Y0\nM30\n");
    ProcessResult r = sim({"run", "moves.nc", "--trace", "trace.jsonl"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json report = output(r);

    std::ifstream in(dir_ / "trace.jsonl");
    ASSERT_TRUE(in.good()) << "no trace file";
    std::string line;
    std::size_t moves = 0;
    double lastT = -1;
    json lastMove;
    bool toolChange = false;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        json e;
        try {
            e = json::parse(line);
        } catch (const json::exception&) {
            ADD_FAILURE() << "trace line " << n << " is not JSON: " << line;
            continue;
        }
        ASSERT_TRUE(e.is_object()) << line;
        ASSERT_TRUE(e.contains("type") && e["type"].is_string()) << line;
        ASSERT_TRUE(e.contains("t") && e["t"].is_number()) << line;
        EXPECT_GE(e["t"].get<double>(), lastT) << "events in time order: " << line;
        lastT = e["t"].get<double>();
        if (e["type"] == "move") {
            ++moves;
            for (const char* end : {"from", "to"}) {
                ASSERT_TRUE(e.contains(end)) << line;
                EXPECT_EQ(keysOf(e[end]), (std::set<std::string>{"X", "Y", "Z", "A", "B"})) << line;
            }
            lastMove = e;
        }
        if (e["type"] == "toolchange") {
            toolChange = true;
            EXPECT_EQ(e.value("from", -1), 1) << line;
            EXPECT_EQ(e.value("to", -1), 2) << line;
        }
    }
    EXPECT_GT(n, 0);
    EXPECT_GE(moves, 3u);
    EXPECT_TRUE(toolChange) << "T2 leaves a toolchange event";
    ASSERT_TRUE(lastMove.is_object());
    for (const char* axis : {"X", "Y", "Z", "A", "B"}) {
        EXPECT_NEAR(lastMove["to"].value(axis, 1e300), report["machine"].value(axis, -1e300), 1e-9)
            << "the last move ends where the report says the machine is (" << axis << ")";
    }
}

// The seed README: the manual's damaged lines "must be rejected with a clear error at the right
// line"; docs/architecture.md: lint findings alarm "once such a line is reached". Running
// `G53 X[#1330+#1300-1]` must not move the spindle to pocket X + tool number - 1.
TEST_F(CliTest, RunRejectsTheManualsDamagedPocketMove) {
    write("pocket.nc", "G53 Z#1306 F#1312\nG53 X[#1330+#1300-1] F#1311\nM30\n");
    ProcessResult r = sim({"run", "pocket.nc", "--tool", "2"});
    json j = output(r);
    EXPECT_NE(j.value("status", ""), "ok") << "machine X ended at " << j["machine"].value("X", json());
    EXPECT_NE(r.exitStatus, kExitOk);
    if (j.value("alarm", json()).is_object()) {
        EXPECT_EQ(j["alarm"].value("line", 0), 2) << j["alarm"];
    }
}

} // namespace

TEST_F(CliTest, ParameterOutsideThePanelRangeIsUsedWithAWarning) {
    fs::path program = write("param.nc", kEndingProgram);
    ProcessResult r = sim({"run", program.string(), "--param", "801=25", "--print", "1301"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("warning: --param 801=25: parameter 801 (Total number of tools) must be a whole number "
                         "from 0 to 20, not 25"),
              std::string::npos)
        << r.err;
    EXPECT_DOUBLE_EQ(json::parse(r.out)["vars"]["1301"].get<double>(), 25.0);
}
