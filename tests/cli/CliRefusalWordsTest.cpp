// The refusals that deeper layers hand up (arc geometry, cutter compensation, G10 L3 tool life
// data, #3003/#3004 and interface output writes, DPRNT without POPEN, G31 and canned cycle words)
// reach the operator by message id: `m350-sim run --lang zh_CN` says each in Chinese on stderr
// while the JSON keeps the English `message` and gives the `message_id`. The notices (a hook
// not run, every tool of a group expired) and m350-sim's own usage errors too.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

namespace {

struct Refusal {
    const char* program;
    std::vector<std::string> options;
    const char* id;
    const char* english; // in the JSON alarm's message
    const char* chinese; // on stderr with --lang zh_CN
};

class CliRefusalWordsTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::copy(fs::path(M350_MACHINES_DIR) / "fanuc-0i", dir_ / "fanuc", fs::copy_options::recursive);
    }

    void expect(const Refusal& refusal) {
        SCOPED_TRACE(refusal.id);
        write("p.nc", refusal.program);
        std::vector<std::string> args{"run", "p.nc", "--lang", "zh_CN"};
        args.insert(args.end(), refusal.options.begin(), refusal.options.end());
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
        json j = output(r);
        ASSERT_TRUE(j["alarm"].is_object()) << j;
        EXPECT_EQ(j["alarm"].value("message_id", ""), refusal.id) << j["alarm"];
        EXPECT_NE(j["alarm"].value("message", "").find(refusal.english), std::string::npos) << j["alarm"];
        EXPECT_NE(r.err.find(refusal.chinese), std::string::npos) << r.err;
    }
};

const std::vector<std::string> kFanuc{"--config", "fanuc"};

} // namespace

TEST_F(CliRefusalWordsTest, ArcGeometryRefusalsAreSaidInChinese) {
    for (const Refusal& refusal : {
             Refusal{"G90 G0 X0 Y0\nG02 X0 Y0 R5 F100\nM30\n", {}, "arc_r_full_circle",
                     "R cannot describe a full circle: use I/J/K", "p.nc:2:1: 报警: R不能指定整圆：请用I/J/K"},
             Refusal{"G90 G0 X0 Y0\nG02 X10 Y0 R2 F100\nM30\n", {}, "arc_r_too_small",
                     "R 2.000 is smaller than half the distance between start and end (5.000)",
                     "R 2.000小于起点到终点距离的一半（5.000）"},
             Refusal{"G90 G0 X0 Y0\nG02 X10 Y0 I0 J1 F100\nM30\n", {}, "arc_end_off_circle",
                     "arc end point is not on the circle: radius at start 1.000, at end ",
                     "圆弧终点不在圆上：起点半径1.000，终点半径"},
             Refusal{"G90 G0 X0 Y0\nG02 X10 Y10 F100\nM30\n", {}, "arc_radius_zero",
                     "arc radius is zero: the center is on the start or end point", "圆弧半径为零：圆心在起点或终点上"},
         }) {
        expect(refusal);
    }
}

TEST_F(CliRefusalWordsTest, CutterCompensationRefusalsAreSaidInChinese) {
    for (const Refusal& refusal : {
             Refusal{"G90 G0 X0 Y0\nG41 D1 G02 X10 Y0 I5 J0 F100\nM30\n", {}, "compensation_start_arc",
                     "cutter compensation must start on a straight move (G0/G1), not an arc",
                     "p.nc:2:1: 报警: 刀具半径补偿须在直线移动（G0/G1）上建立，不能在圆弧上建立"},
             Refusal{"G90 G0 X0 Y0\nG01 G41 D1 X20 F100\nM30\n", {}, "compensation_entry_short",
                     "cutter compensation entry move of length 20.000 is not longer than the cutter radius",
                     "刀补建立移动长度20.000不大于刀具半径"},
             Refusal{"G90 G0 X0 Y0\nG01 G41 D1 X200 F100\nG42 X300\nM30\n", {}, "compensation_switch_side",
                     "cannot switch between G41 and G42 while compensating: program G40 first",
                     "p.nc:3:1: 报警: 刀补中不能在G41和G42之间切换：请先用G40取消刀补"},
             Refusal{"G90 G0 X0 Y0\nG01 G41 D1 X200 F100\nG40 G02 X400 I100\nM30\n", {}, "compensation_end_arc",
                     "cutter compensation must end (G40) on a straight move, not an arc",
                     "刀具半径补偿须在直线移动上取消（G40），不能在圆弧上取消"},
             Refusal{"G90 G0 X0 Y0\nG01 G41 D1 X200 F100\nG02 X220 I10\nM30\n", {}, "compensation_gouge_arc",
                     "cutter radius too large for the arc of radius 10.000 (gouge)", "刀具半径对半径为10.000的圆弧过大（过切）"},
             Refusal{"G90 G0 X0 Y0\nG01 G41 D1 X200 F100\nY200\nX210\nY-200\nM30\n", {}, "compensation_gouge_corner",
                     "too large for the inside corner at X200.000 Y200.000 (gouge)", "对X200.000 Y200.000处的内拐角过大（过切）"},
         }) {
        expect(refusal);
    }
}

TEST_F(CliRefusalWordsTest, ToolLifeDataEntryRefusalsAreSaidInChinese) {
    const std::vector<std::string> noExt{"--config", "fanuc", "--param", "6801=0"};
    for (const Refusal& refusal : {
             Refusal{"G10 L3 P5\nM30\n", kFanuc, "tool_life_entry_mode",
                     "G10 L3 P5: P1 adds or changes groups, P2 deletes them, no P enters all data anew",
                     "G10 L3 P5：P1添加或修改刀具组，P2删除刀具组，不带P则重新输入全部数据"},
             Refusal{"G10 L3 P1\nM30\n", noExt, "tool_life_entry_extended",
                     "G10 L3 P1 (add or change groups) needs the extended tool life management",
                     "G10 L3 P1（添加或修改刀具组）需要扩展刀具寿命管理"},
             Refusal{"G10 L3\nP1 L2 T11\nM30\n", kFanuc, "tool_life_entry_group_and_tool",
                     "G10 L3 data: a group (P L Q) and a tool (T H D) go in separate blocks",
                     "G10 L3数据：刀具组（P L Q）和刀具（T H D）须分段输入"},
             Refusal{"G10 L3\nP999 L2\nM30\n", kFanuc, "tool_life_entry_group_beyond",
                     "G10 L3 data: group P999 is beyond the 16 groups the memory holds (GS1/GS2)",
                     "G10 L3数据：刀具组P999超出存储器可容纳的16个刀具组（GS1/GS2）"},
             Refusal{"G10 L3\nP1\nM30\n", kFanuc, "tool_life_entry_needs_life",
                     "G10 L3 data: group P1 needs its life L (1 or more)", "G10 L3数据：刀具组P1需要寿命值L（1或以上）"},
             Refusal{"G10 L3\nP1 L2 Q3\nM30\n", kFanuc, "tool_life_entry_q", "G10 L3 data: Q1 counts uses, Q2 counts minutes",
                     "G10 L3数据：Q1按使用次数计，Q2按分钟计"},
             Refusal{"G10 L3\nP1 L2\nT11\nP1 L2\nM30\n", kFanuc, "tool_life_entry_twice",
                     "G10 L3 data: group P1 is entered twice", "p.nc:4:1: 报警: G10 L3数据：刀具组P1输入了两次"},
             Refusal{"G10 L3\nT11\nM30\n", kFanuc, "tool_life_entry_tool_first",
                     "G10 L3 data: a tool T needs its group (P_ L_) in a block before it",
                     "G10 L3数据：刀具T之前须有一段给出其刀具组（P_ L_）"},
             Refusal{"G10 L3\nP1 L2\nT0\nM30\n", kFanuc, "tool_life_entry_ranges",
                     "G10 L3 data: T takes 1-9999, H and D 0-999", "G10 L3数据：T取1-9999，H和D取0-999"},
             Refusal{"G10 L3\nH5\nM30\n", kFanuc, "tool_life_entry_block",
                     "G10 L3 data: a block is a group (P L [Q]) or one of its tools (T [H] [D]); end with G11",
                     "G10 L3数据：每段为一个刀具组（P L [Q]）或其中一把刀具（T [H] [D]）；用G11结束"},
             Refusal{"G10 L3\nP1 L2\nG11\nM30\n", kFanuc, "tool_life_entry_no_tools", "G10 L3 data: group 1 has no tools",
                     "G10 L3数据：刀具组1没有刀具"},
             Refusal{"G10 L3 P2\nP1 L2\nM30\n", kFanuc, "tool_life_delete_only_p",
                     "G10 L3 P2 (delete): give only the group numbers P", "G10 L3 P2（删除）：只给出刀具组号P"},
             Refusal{"G10 L3 P2\nP7\nM30\n", kFanuc, "tool_life_delete_missing", "G10 L3 P2: there is no group 7 to delete",
                     "G10 L3 P2：没有可删除的刀具组7"},
         }) {
        expect(refusal);
    }
}

TEST_F(CliRefusalWordsTest, ToolLifeSelectionRefusalsAndTheExpiredNoticeAreSaidInChinese) {
    for (const Refusal& refusal : {
             Refusal{"G10 L3\nP1 L2\nT11 H11\nG11\nT105 M06\nM30\n", kFanuc, "tool_life_group_missing",
                     "T105: tool life group 5 is not entered (T100+n selects group n; enter groups with G10 L3)",
                     "p.nc:5:1: 报警: T105：刀具寿命组5未输入（T100+n选择刀具组n；用G10 L3输入刀具组）"},
             Refusal{"G10 L3\nP1 L2\nT11 H11\nG11\nG43 H99 Z0\nM30\n", kFanuc, "tool_life_offset_none",
                     "H99: no tool of a tool life group is in use (select a group with T101.. and change to it first)",
                     "p.nc:5:5: 报警: H99：没有正在使用的刀具寿命组刀具（请先用T101..选择刀具组并换上该刀具）"},
         }) {
        expect(refusal);
    }
    // T11 lives one use: the next run's T101 finds every tool of group 1 expired and goes on with it
    write("enter.nc", "G10 L3\nP1 L1 Q1\nT11 H11\nG11\nT101 M06\nM30\n");
    ASSERT_EQ(sim({"run", "enter.nc", "--config", "fanuc"}).exitStatus, kExitOk);
    write("again.nc", "T101 M06\nM30\n");
    ProcessResult r = sim({"run", "again.nc", "--config", "fanuc", "--lang", "zh_CN"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_NE(r.err.find("刀具寿命：刀具组1的所有刀具均已到寿命(T11 1/1 次)：继续使用T11"), std::string::npos) << r.err;
    json j = output(r);
    ASSERT_EQ(j["message_ids"].size(), 1u) << j;
    EXPECT_EQ(j["message_ids"][0].value("message_id", ""), "tool_life_expired_count");
    EXPECT_NE(j["messages"][0].get<std::string>().find("tool life: every tool of group 1 has reached its life (T11 1/1 uses)"),
              std::string::npos)
        << j["messages"];
}

TEST_F(CliRefusalWordsTest, SystemVariableAndDeviceRefusalsAreSaidInChinese) {
    const std::vector<std::string> fanuc{"--dialect", "fanuc"};
    for (const Refusal& refusal : {
             Refusal{"#3004=9\nM30\n", fanuc, "operation_control_3004",
                     "#3004 = 9: it takes 0 to 7 (bit 0 no feed hold, bit 1 no feed override, bit 2 no exact stop check)",
                     "#3004 = 9：取值为0到7（位0：进给保持无效，位1：进给倍率无效，位2：不作准确停止检查）"},
             Refusal{"#3003=1.5\nM30\n", fanuc, "operation_control_3003",
                     "#3003 = 1.5: it takes 0 to 3 (bit 0 no single block stop, bit 1 no wait for M, S, T completion)",
                     "#3003 = 1.5：取值为0到3（位0：不作单段停止，位1：不等待M、S、T完成）"},
             Refusal{"#1100=2\nM30\n", fanuc, "interface_output_bit", "#1100 = 2: an interface output is 0 or 1",
                     "#1100 = 2：接口输出只能为0或1"},
             Refusal{"#1132=-1\nM30\n", fanuc, "interface_outputs_range", "#1132 = -1: it takes a whole number from 0 to 65535",
                     "#1132 = -1：须为0到65535的整数"},
             Refusal{"DPRNT[X]\nM30\n", fanuc, "output_without_popen",
                     "DPRNT without POPEN: the external output device is closed (open it with POPEN before DPRNT, close "
                     "it with PCLOS)",
                     "DPRNT之前没有POPEN：外部输出设备未打开（在DPRNT之前用POPEN打开，用PCLOS关闭）"},
         }) {
        expect(refusal);
    }
}

TEST_F(CliRefusalWordsTest, G31AndRepeatCountRefusalsAreSaidInChinese) {
    for (const Refusal& refusal : {
             Refusal{"G31 X10 F100\nM30\n", {}, "word_g31_needs_port", "G31: G31 needs P<input 1-24> and L<level>",
                     "G31：G31需要P<输入1-24>和L<电平>"},
             Refusal{"G31 X10 F100\nM30\n", {"--dialect", "fanuc"}, "word_g31_no_skip",
                     "G31: no skip signal: the fixed setter input (params 575-577) is not set",
                     "G31：没有跳转信号：未设置固定对刀仪的输入（参数575-577）"},
             Refusal{"G90 G81 X0 Y0 Z-5 R2 K1.5 F100\nM30\n", {"--dialect", "fanuc"}, "word_repeat_count",
                     "K1.5: the repeat count of a canned cycle is a whole number 0-9999",
                     "p.nc:1:22: 报警: K1.5：固定循环的重复次数须为0-9999的整数"},
         }) {
        expect(refusal);
    }
}

// error.nc runs after an alarm: one it cannot read or parse is said on the message line, by id.
TEST_F(CliRefusalWordsTest, AHookThatCannotRunIsSaidInChinese) {
    fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", dir_ / "m350", fs::copy_options::recursive);
    write("div.nc", "#1=0\n#2=1/#1\nM30\n");
    write("m350/error.nc", "#1=[2\nM30\n");
    ProcessResult r = sim({"run", "div.nc", "--config", "m350", "--lang", "zh_CN"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    EXPECT_NE(r.err.find("error.nc:1:6: 缺少 ']'，无法关闭第4列的 '['，实际为 行尾（error.nc未运行）"), std::string::npos)
        << r.err;
    json j = output(r);
    ASSERT_EQ(j["message_ids"].size(), 1u) << j;
    EXPECT_EQ(j["message_ids"][0].value("message_id", ""), "hook_not_run_syntax");
    EXPECT_EQ(j["messages"][0], "error.nc:1:6: missing ']' to close the '[' at column 4, found the end of the line "
                                "(error.nc not run)");

    write("m350/error.nc", "M30\n\xff\xfe\x80\x80\x81\n");
    r = sim({"run", "div.nc", "--config", "m350", "--lang", "zh_CN"});
    EXPECT_NE(r.err.find("error.nc：未运行：文件既不是有效的 UTF-8 也不是 GBK（第一个错误字节在第2行第1列）"), std::string::npos)
        << r.err;
    j = output(r);
    ASSERT_EQ(j["message_ids"].size(), 1u) << j;
    EXPECT_EQ(j["message_ids"][0].value("message_id", ""), "hook_not_run");
    EXPECT_EQ(j["messages"][0], "error.nc: not run: file is neither valid UTF-8 nor GBK (first bad byte at line 2, column 1)");
}

TEST_F(CliRefusalWordsTest, UsageErrorsAreSaidInTheLangLanguage) {
    write("q.nc", "M30\n");
    struct Usage {
        std::vector<std::string> options;
        const char* english;
        const char* chinese;
    };
    for (const Usage& usage : {
             Usage{{"--param", "5=abc"}, "m350-sim: --param: 'abc' is not a number", "m350-sim: --param: 'abc'不是数字"},
             Usage{{"--fault", "IN12=wobbly:1"}, "m350-sim: --fault: 'wobbly' is no fault: delayed, bouncing or stuck",
                   "m350-sim: --fault: 'wobbly'不是故障类型：delayed（延迟）、bouncing（抖动）或stuck（卡死）"},
             Usage{{"--input", "IN30=1"}, "m350-sim: --input: inputs are IN01-IN24", "m350-sim: --input: 输入为IN01-IN24"},
             Usage{{"--break", "T1=0"}, "m350-sim: --break: 'T1=0': the tool breaks off more than 0 mm, at 0 s or later",
                   "m350-sim: --break: 'T1=0'：断掉的长度须大于0毫米，时间须为0秒或以后"},
             Usage{{"--tool", "99"},
                   "m350-sim: --tool 99: tools run from 0 (empty spindle) to 36 on this machine (magazine capacity 16, "
                   "plus 20 virtual tools)",
                   "m350-sim: --tool 99：本机床的刀号为0（主轴无刀）到36（刀库容量16，另加20把虚拟刀具）"},
             Usage{{"--print", "9876"}, "m350-sim: --print 9876: #9876 does not exist in the m350 dialect",
                   "m350-sim: 选项--print 9876：m350 方言中没有变量 #9876（未定义）"},
             Usage{{"--var", "5021=1", "--dialect", "fanuc"}, "m350-sim: --var 5021=...: #5021 (machine position) is read-only",
                   "m350-sim: --var 5021=...：#5021 (机床坐标)为只读变量"},
             Usage{{"--dialect", "fanuc", "--param", "6050=100", "--param", "6052=100"},
                   "m350-sim: --param 6052: parameter 6052 = 100 makes G100 call O9012, but parameter 6050 = 100 "
                   "(--param 6050) already makes it call O9010: keep one of them",
                   "m350-sim: --param 6052: 参数6052 = 100使G100调用O9012，但参数6050 = 100 (--param 6050)已使其调用O9010"},
         }) {
        SCOPED_TRACE(usage.english);
        std::vector<std::string> args{"run", "q.nc"};
        args.insert(args.end(), usage.options.begin(), usage.options.end());
        ProcessResult english = sim(args);
        EXPECT_EQ(english.exitStatus, kExitUsage) << english.err;
        EXPECT_NE(english.err.find(usage.english), std::string::npos) << english.err;
        args.insert(args.begin() + 2, {"--lang", "zh_CN"}); // --lang before the option it refuses
        ProcessResult chinese = sim(args);
        EXPECT_EQ(chinese.exitStatus, kExitUsage) << chinese.err;
        EXPECT_NE(chinese.err.find(usage.chinese), std::string::npos) << chinese.err;
    }
    // the hint after a usage error of the command line is said in the language too
    ProcessResult english = sim({"run", "q.nc", "--param", "5=abc"});
    EXPECT_NE(english.err.find("Run 'm350-sim --help' for usage."), std::string::npos) << english.err;
    ProcessResult chinese = sim({"run", "q.nc", "--param", "5=abc", "--lang", "zh_CN"}); // --lang after it
    EXPECT_NE(chinese.err.find("m350-sim: --param: 'abc'不是数字\n用法请运行'm350-sim --help'查看。"), std::string::npos)
        << chinese.err;
}

} // namespace m350::clitest
