// Every word in the operator's language: `m350-sim run/check --lang zh_CN` says the alarms, the
// parser's and the checker's findings and the run's notices from the message table
// (translations/messages.tsv) in Chinese, while the JSON keeps the English `message` and gives the
// `message_id`; and every alarm and finding of the golden corpus carries an id.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <set>

namespace m350::clitest {

TEST_F(CliTest, AMacroAlarmIsSaidInChinese) {
    write("div.nc", "#1=0\n#2=5/#1\nM30\n");
    ProcessResult r = sim({"run", "div.nc", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("div.nc:2:5: 报警: 除数为零"), std::string::npos) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("message", ""), "division by zero"); // the JSON keeps the English
    EXPECT_EQ(j["alarm"].value("message_id", ""), "division_by_zero");
    ProcessResult english = sim({"run", "div.nc"});
    EXPECT_NE(english.err.find("div.nc:2:5: alarm: division by zero"), std::string::npos) << english.err;
}

TEST_F(CliTest, AnInterpreterAlarmIsSaidInChinese) {
    write("hpcc.nc", "G90\nG05.1 Q1\nM30\n");
    ProcessResult r = sim({"run", "hpcc.nc", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("hpcc.nc:2:1: 报警: G5.1：本机床不支持此 G 代码"), std::string::npos) << r.err;
    EXPECT_EQ(output(r)["alarm"].value("message", ""), "G5.1: not a G code this machine knows");
    write("drill.nc", "G90 G81 X0 Y0 Z-5 F100\nM30\n");
    ProcessResult cycle = sim({"run", "drill.nc", "--dialect", "fanuc", "--lang", "zh_CN"});
    EXPECT_EQ(cycle.exitStatus, kExitAlarm) << cycle.err;
    EXPECT_NE(cycle.err.find("报警: G81 的第一个程序段需要 R（开始钻孔的R点平面）"), std::string::npos) << cycle.err;
}

TEST_F(CliTest, AnUndefinedVariableIsSaidInChinese) {
    write("var.nc", "#1=#9876\nM30\n");
    ProcessResult r = sim({"run", "var.nc", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("报警: m350 方言中没有变量 #9876（未定义"), std::string::npos) << r.err;
}

TEST_F(CliTest, ASyntaxErrorIsSaidInChineseByCheckAndRun) {
    write("if.nc", "#1=1\nIF [#1 GT 0] X10\nM30\n");
    ProcessResult check = sim({"check", "if.nc", "--lang", "zh_CN"});
    EXPECT_EQ(check.exitStatus, kExitError);
    EXPECT_NE(check.err.find("if.nc:2:14: IF 条件后须跟 GOTOn 或 THEN，实际为 'X'"), std::string::npos) << check.err;
    json j = output(check);
    ASSERT_EQ(j["diagnostics"].size(), 1u) << j;
    EXPECT_EQ(j["diagnostics"][0].value("message", ""), "IF condition must be followed by GOTOn or THEN, found 'X'");
    EXPECT_EQ(j["diagnostics"][0].value("message_id", ""), "parse_if_goto_then");
    ProcessResult run = sim({"run", "if.nc", "--lang", "zh_CN"});
    EXPECT_EQ(run.exitStatus, kExitError);
    EXPECT_NE(run.err.find("if.nc:2:14: IF 条件后须跟 GOTOn 或 THEN，实际为 'X'"), std::string::npos) << run.err;
    // the words of the finding itself are said too: the end of the line
    write("then.nc", "#1=1\nIF [#1 GT 0] THEN\nM30\n");
    ProcessResult then = sim({"check", "then.nc", "--lang", "zh_CN"});
    EXPECT_NE(then.err.find("then.nc:2:18: THEN 后须跟赋值语句（如 #1 = 0），实际为 行尾"), std::string::npos) << then.err;
    ProcessResult english = sim({"check", "then.nc"});
    EXPECT_NE(english.err.find("THEN must be followed by an assignment such as #1 = 0, found the end of the line"),
              std::string::npos)
        << english.err;
}

TEST_F(CliTest, ALintAndAFlowFindingAreSaidInChinese) {
    write("lint.nc", "#1=3\nG53 X[#1330+#1] Y0\nGOTO 40\nM30\n");
    ProcessResult r = sim({"check", "lint.nc", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find("lint.nc:2:5: X[#1330+#1] 是加上 #1330 的值，而不是按序号取刀位X坐标表(参数830-845)中的值"
                         "（是否应为 X#[1330+#1]？）"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("lint.nc:3:6: GOTO40：本程序中没有 N40"), std::string::npos) << r.err;
    ProcessResult english = sim({"check", "lint.nc"});
    EXPECT_NE(english.err.find("lint.nc:2:5: X[#1330+#1] adds the value of #1330 instead of indexing the tool pocket X "
                               "table (params 830-845) (did you mean X#[1330+#1]?)"),
              std::string::npos)
        << english.err;
    EXPECT_NE(english.err.find("lint.nc:3:6: GOTO40: there is no N40 in this program"), std::string::npos) << english.err;
}

TEST_F(CliTest, TheRunsNoticesHaveIdsAndAreSaidInTheLanguageAsked) {
    write("long.nc", "G91 G01 X100 F600\nX100\nM30\n");
    ProcessResult r = sim({"run", "long.nc", "--pause-at", "1", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    ASSERT_EQ(j["messages"].size(), 2u) << j;
    EXPECT_EQ(j["messages"][0], "PAUSE pressed at 1 s (long.nc:1)");
    EXPECT_EQ(j["messages"][1], "PAUSE: START pressed (run without an operator)");
    ASSERT_EQ(j["message_ids"].size(), 2u) << j;
    EXPECT_EQ(j["message_ids"][0].value("message_id", ""), "notice_pause_pressed");
    EXPECT_EQ(j["message_ids"][0]["message_arguments"], (json{"1", "long.nc", "1"}));
    EXPECT_NE(r.err.find("m350-sim: 信息: 1秒时按下进给保持（long.nc:1）"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("m350-sim: 信息: 进给保持：已按循环启动（无人值守运行）"), std::string::npos) << r.err;
    // without --lang the notices stay in the JSON only, as before
    ProcessResult quiet = sim({"run", "long.nc", "--pause-at", "1"});
    EXPECT_EQ(quiet.err.find("PAUSE pressed"), std::string::npos) << quiet.err;
}

} // namespace m350::clitest
