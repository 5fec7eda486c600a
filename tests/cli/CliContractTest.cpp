// m350-sim's contract: exit statuses, one JSON object on stdout, file:line:col on stderr,
// check's listing, and errors found before a run.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

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
        {"run", "ok.nc", "--print", "99999999"},  // no machine has such a variable
        {"run", "ok.nc", "--print", "5001"},      // a FANUC variable, not the M350's
        {"import", "backup", "--into", ""},       // an empty name is no folder
        {"import", "", "--into", "machine"},
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

// --version names the version and the commit the build was configured at.
TEST_F(CliTest, VersionNamesTheVersionAndTheCommit) {
    ProcessResult r = sim({"--version"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(r.out.rfind("m350-sim " M350_VERSION " (commit ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find(')'), std::string::npos) << r.out;
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
                      "G01 X#1+ F100\n" // line 4: the sum has no second operand
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

} // namespace m350::clitest
