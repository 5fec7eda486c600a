// Issue 13: `check` said ok to programs that alarm on line 1. What is knowable without running is
// reported in check's layout, at the place the run's alarm names.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

namespace {

struct Expected {
    const char* program;
    int line;
    int column;
    const char* message;
};

} // namespace

TEST_F(CliTest, CheckReportsWhatWouldAlarmWithoutRunning) {
    const Expected cases[] = {
        {"G1 X1 X2\n", 1, 7, "X appears twice in one block"},
        {"G999999\n", 1, 1, "G999999: not a G code this machine knows"},
        {"#99999999=5\n", 1, 1, "#[99999999]: variable numbers are whole numbers from 0 to 9999"},
        {"#1=#[1E0]\n", 0, 0, ""}, // an E exponent is a parse error already (not checked further)
        {"#1520=1\n", 1, 1, "cannot write #1520 (input IN01): it is read-only"},
        {"#1=1/0\n", 1, 5, "division by zero"},
        {"G0 X1\n#2=#[2+3]+#[99999+1]\n", 2, 11, "#[100000]: variable numbers are whole numbers from 0 to 9999"},
        {"M98 P200\nM30\nO200\nG0 X1\nM98 P200\nM99\n", 5, 5, "O200 calls itself on every pass"},
        // through another program, the call before a guard that comes too late
        {"M98 P100\nM30\nO100\nG65 P200 A1\nM99\nO200\nM98 P100\nIF [#1 GT 5] GOTO 9\nN9 M99\n", 4, 5,
         "O100 calls itself through O100 -> O200 -> O100 on every pass"},
    };
    for (const Expected& c : cases) {
        write("c.nc", c.program);
        ProcessResult r = sim({"check", "c.nc"});
        EXPECT_EQ(r.exitStatus, kExitError) << c.program << r.err;
        json j = output(r);
        EXPECT_EQ(j.value("status", ""), "error") << c.program;
        ASSERT_FALSE(j["diagnostics"].empty()) << c.program;
        if (c.line == 0) {
            continue;
        }
        const json& d = j["diagnostics"][0];
        EXPECT_EQ(d.value("line", 0), c.line) << c.program << d;
        EXPECT_EQ(d.value("column", 0), c.column) << c.program << d;
        EXPECT_NE(d.value("message", "").find(c.message), std::string::npos) << c.program << d;
        EXPECT_NE(r.err.find("c.nc:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": " + c.message),
                  std::string::npos)
            << r.err;
        ProcessResult run = sim({"run", "c.nc", "--max-sim-time", "5"});
        EXPECT_EQ(run.exitStatus, kExitAlarm) << c.program << " the run alarms too: " << run.err;
    }
}

TEST_F(CliTest, CheckDoesNotFlagWhatMayBeFine) {
    for (const char* program : {"G65 P100 I1 J2 K3 I4 J5 K6\nM30\nO100\nM99\n", // argument spec II repeats I J K
                                "O100\n#1=#1+1\nIF [#1 LT 3] GOTO 9\nM99\nN9 M98 P100\nM99\n", // a guarded self-call
                                "O100\nM98 P200\nM99\nO200\nIF [#1 GT 0] GOTO 9\nM98 P100\nN9 M99\n", // guarded in O200
                                "O100\nM99\nM98 P100\n", // M99 returns before the call
                                "#1=#100/#101\nG1 X#[#1+1] F100\nM30\n", "G54 G0 X1\nG4 P100\nM30\n"}) {
        write("ok.nc", program);
        ProcessResult r = sim({"check", "ok.nc"});
        EXPECT_EQ(r.exitStatus, kExitOk) << program << r.err;
    }
}

// What a finding repeats of the program is cut to 512 bytes, as echoed text is everywhere: a code
// of 300 digits on a 100 kB line reads 1e+300, and a cycle through 64 programs names the first of
// them and says how much of the chain was left out.
TEST_F(CliTest, CheckFindingsKeepWhatTheyQuoteShort) {
    std::string line = "G" + std::string(300, '9');
    while (line.size() < 100000) {
        line += " X1";
    }
    std::string cycle = "M98 P1000\nM30\n";
    for (int n = 1000; n < 1064; ++n) {
        cycle += "O" + std::to_string(n) + "\nM98 P" + std::to_string(n == 1063 ? 1000 : n + 1) + "\nM99\n";
    }
    write("long.nc", line + "\n" + cycle);
    ProcessResult r = sim({"check", "long.nc"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err.substr(0, 2000);
    const json diagnostics = output(r)["diagnostics"];
    ASSERT_GT(diagnostics.size(), 3u);
    EXPECT_EQ(diagnostics[0].value("message", ""), "G1e+300: not a G code this machine knows") << diagnostics[0];
    const std::string limitNote = "… (1000000 more bytes)";
    bool cycleSeen = false;
    for (const json& d : diagnostics) {
        const std::string message = d.value("message", "");
        EXPECT_LE(message.size(), 512u + limitNote.size()) << message;
        if (message.rfind("O1000 calls itself through O1000 -> O1001 -> ", 0) == 0) {
            cycleSeen = true;
            EXPECT_NE(message.find(" more bytes)"), std::string::npos) << message;
        }
    }
    EXPECT_TRUE(cycleSeen) << r.err.substr(r.err.size() > 3000 ? r.err.size() - 3000 : 0);
    EXPECT_LT(r.err.size(), 1001u * (512u + 100u)) << "stderr lists the same bounded findings";
}

// Issue 26: check walked a generated 40,000-term sum recursively (exit 139, a stack overflow) and
// asked each node again whether its operands were constant (quadratic: 30,000 terms took 2.5 s).
// Now one pass with an explicit stack: 200,000 terms, and 50,000 inside an address, check at once
// and a 1/0 after them is still found.
TEST_F(CliTest, CheckOfAHugeExpressionNeedsNoDeepStack) {
    std::string sum = "#1=#2";
    for (int i = 1; i < 200000; ++i) {
        sum += "+#2";
    }
    std::string address = "G1 X[#1330";
    for (int i = 0; i < 50000; ++i) {
        address += "+1";
    }
    write("huge.nc", sum + "\n" + address + "] F100\n#3=1/0+#2\nM30\n");
    ProcessResult r = sim({"check", "huge.nc"});
    EXPECT_EQ(r.exitStatus, kExitError) << r.err.substr(0, 2000);
    bool divisionFound = false;
    const json result = output(r);
    for (const json& d : result["diagnostics"]) {
        divisionFound |= d.value("line", 0) == 3 && d.value("message", "") == "division by zero";
    }
    EXPECT_TRUE(divisionFound) << r.out.substr(0, 2000);
}

// Issue 26: a DPRNT of 100,000 items parsed in quadratic time (each item's column counted from the
// line's start: 77 s); the columns are still right, here of a bad character after them.
TEST_F(CliTest, ADprntOfManyItemsParsesInOnePass) {
    std::string items = "DPRNT[";
    for (int i = 0; i < 100000; ++i) {
        items += "X#1[53]*";
    }
    const std::size_t badColumn = items.size() + 1;
    write("many.nc", "POPEN\n" + items + "x]\nPCLOS\nM30\n");
    ProcessResult r = sim({"check", "many.nc", "--dialect", "fanuc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find("many.nc:2:" + std::to_string(badColumn) + ": DPRNT text may hold capital letters"),
              std::string::npos)
        << r.err.substr(0, 2000);
}

// Issue 26: check said ok to M999999, which every run of it alarms on an M350 (the firmware's own M
// codes and slib-m.nc's handlers, nothing else); a FANUC's PMC takes any M code.
TEST_F(CliTest, CheckKnowsTheM350sMCodes) {
    write("m.nc", "M3 S1000\nM999999\nM123\nM8\nM30\n");
    ProcessResult m350 = sim({"check", "m.nc"});
    EXPECT_EQ(m350.exitStatus, kExitError);
    EXPECT_NE(m350.err.find("m.nc:2:1: M999999: no such M code (and no O1009999 handler in slib-m.nc)"),
              std::string::npos)
        << m350.err;
    EXPECT_NE(m350.err.find("m.nc:3:1: M123: no such M code (and no O10123 handler in slib-m.nc)"), std::string::npos)
        << m350.err;
    ProcessResult run = sim({"run", "m.nc"});
    EXPECT_NE(run.err.find("m.nc:2:1: alarm: M999999: no such M code"), std::string::npos) << run.err;
    ProcessResult fanuc = sim({"check", "m.nc", "--dialect", "fanuc"});
    EXPECT_EQ(fanuc.exitStatus, kExitOk) << fanuc.err;
}

TEST_F(CliTest, CheckOnAMissingFileKeepsTheCheckLayout) {
    ProcessResult r = sim({"check", "missing.nc"});
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(keysOf(j), (std::set<std::string>{"status", "diagnostics"})) << j;
    ASSERT_EQ(j["diagnostics"].size(), 1u);
    EXPECT_EQ(j["diagnostics"][0].value("file", ""), "missing.nc");
    EXPECT_NE(j["diagnostics"][0].value("message", "").find("cannot open program"), std::string::npos);
}

} // namespace m350::clitest

namespace m350::clitest {

// Issue 28: `check --lint` warns about what a trainee's macro gets wrong though it runs, at the
// place, in the language asked; without --lint `check` says only what would alarm.
TEST_F(CliTest, CheckLintWarnsAboutATraineesMacroInChinese) {
    write("t.nc", "#13=7\n"
                  "WHILE [#[1520+#13-1] NE 0] DO1 (wait for IN07)\n"
                  "G04 P10\n"
                  "END1\n"
                  "#1552=1\n"
                  "G0 X#5\n"
                  "IF [#1521 EQ 1] GOTO9\n"
                  "#1552=0\n"
                  "T2 M6\n"
                  "N9 M30\n");
    ProcessResult plain = sim({"check", "t.nc"});
    EXPECT_EQ(plain.exitStatus, kExitOk) << plain.err;
    EXPECT_TRUE(output(plain)["diagnostics"].empty()) << plain.out;

    ProcessResult r = sim({"check", "t.nc", "--lint", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitOk) << "warnings do not fail the check: " << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "ok");
    std::vector<std::string> ids;
    for (const json& d : j["diagnostics"]) {
        EXPECT_EQ(d.value("severity", ""), "warning") << d;
        ids.push_back(d.value("message_id", ""));
    }
    EXPECT_EQ(ids, (std::vector<std::string>{"lint_input_wait", "lint_output_left_on",
                                             "lint_read_before_set", "lint_m30_after_m6"}));
    for (const char* line : {"t.nc:2:1: 警告: WHILE 等待输入 #[1520+#13-1]，既无超时也无出口",
                             "t.nc:5:1: 警告: 输出 #1552 在此打开，程序经某一路径到达第10行的 M30 时仍未关闭",
                             "t.nc:6:5: 警告: #5 在本程序给它赋值之前就被读取", "t.nc:10:4: 警告: M6 之后紧接 M30"}) {
        EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
    }

    // a '(' in a comment: the comment ends at the first ')', and the warning explains the error after it
    write("n.nc", "G04 P10 (dwell (ms))\nM30\n");
    ProcessResult nested = sim({"check", "n.nc", "--lint", "--lang", "zh_CN"});
    EXPECT_EQ(nested.exitStatus, kExitError);
    EXPECT_NE(nested.err.find("n.nc:1:16: 警告: 注释中又有“(”：注释不能嵌套，注释在第一个“)”处结束"), std::string::npos)
        << nested.err;
    EXPECT_NE(nested.err.find("n.nc:1:20: "), std::string::npos) << nested.err;
}

} // namespace m350::clitest
