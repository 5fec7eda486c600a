// What m350-sim says about the files around a run (a hook the machine folder lacks, an output
// naming an input, a program or trace file it cannot have, tool.tbl and toollife.txt lines it
// skips, a parameter value the panel would refuse) is said by message id: in Chinese on stderr
// with --lang zh_CN, in English without it, and the JSON keeps the English with the message_id.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace m350::clitest {

namespace {

class CliFileWordsTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", dir_ / "m350", fs::copy_options::recursive);
        write("p.nc", "M30\n");
    }

    std::string read(const std::string& name) const {
        std::ifstream in(dir_ / name, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    // stderr of the same command in English and with --lang zh_CN
    std::pair<ProcessResult, ProcessResult> both(std::vector<std::string> args) {
        ProcessResult english = sim(args);
        args.insert(args.end(), {"--lang", "zh_CN"});
        return {english, sim(args)};
    }
};

#define EXPECT_SAYS(result, text) EXPECT_NE((result).err.find(text), std::string::npos) << (result).err

} // namespace

TEST_F(CliFileWordsTest, AHookTheMachineFolderLacksIsSaidWithWhatRunsItInTheLanguage) {
    auto [english, chinese] = both({"hook", "key-3", "--config", "m350"});
    EXPECT_EQ(english.exitStatus, kExitUsage) << english.err;
    EXPECT_SAYS(english, "hook key-3: the machine folder m350 has no key-3.nc (run at: K3 while param 212 = 0); "
                         "its hook files: T, fndzero");
    EXPECT_EQ(chinese.exitStatus, kExitUsage) << chinese.err;
    EXPECT_SAYS(chinese, "m350-sim: 挂钩key-3：机床文件夹m350中没有key-3.nc（运行时机：参数212 = 0时的K3键）；其中的挂钩文件：T, fndzero");
    EXPECT_SAYS(chinese, "；可用的挂钩：T, ALL_T, fndzero");
    fs::remove(dir_ / "m350" / "T.nc");
    for (const char* hook : {"fndzero", "fndX", "fndY", "fndZ", "gotozero", "probe", "mulprobe", "key-1", "M3", "M4", "M5"}) {
        fs::remove(dir_ / "m350" / (std::string(hook) + ".nc"));
    }
    ProcessResult none = sim({"hook", "fndzero", "--config", "m350", "--lang", "zh_CN"});
    EXPECT_SAYS(none, "（运行时机：回机械原点，全部轴）；其中的挂钩文件：无；");
}

TEST_F(CliFileWordsTest, AnOutputNamingAnInputIsRefusedInTheLanguage) {
    auto [english, chinese] = both({"run", "p.nc", "--trace", "p.nc"});
    EXPECT_EQ(english.exitStatus, kExitUsage) << english.err;
    EXPECT_SAYS(english, "m350-sim: --trace p.nc is the program of this run (p.nc): refused, nothing was written");
    EXPECT_EQ(chinese.exitStatus, kExitUsage) << chinese.err;
    EXPECT_SAYS(chinese, "m350-sim: --trace p.nc是本次运行的程序（p.nc）：已拒绝，未写入任何内容");
    ProcessResult folder = sim({"run", "p.nc", "--config", "m350", "--tools-out", "m350/params.toml", "--lang", "zh_CN"});
    EXPECT_EQ(folder.exitStatus, kExitUsage) << folder.err;
    EXPECT_SAYS(folder, "m350-sim: --tools-out m350/params.toml是本次运行的机床文件夹中的文件（");
    EXPECT_EQ(std::string("M30\n"), read("p.nc"));
}

TEST_F(CliFileWordsTest, AProgramOrTraceFileItCannotHaveIsAFileErrorByIdInTheLanguage) {
    auto [english, chinese] = both({"run", "nowhere.nc"});
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "nowhere.nc: cannot open program: no such file");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "nowhere.nc: 无法打开程序：文件不存在");
    json j = output(chinese);
    EXPECT_EQ(j["alarm"].value("code", ""), "file_error") << j;
    EXPECT_EQ(j["alarm"].value("message", ""), "cannot open program: no such file") << j;
    EXPECT_EQ(j["alarm"].value("message_id", ""), "program_missing") << j;

    fs::create_directory(dir_ / "folder.nc");
    ProcessResult folder = sim({"check", "folder.nc", "--lang", "zh_CN"});
    EXPECT_EQ(folder.exitStatus, kExitError);
    EXPECT_SAYS(folder, "无法打开程序：这是文件夹、FIFO或设备，不是程序文件");
    j = output(folder);
    ASSERT_EQ(j["diagnostics"].size(), 1u) << j;
    EXPECT_EQ(j["diagnostics"][0].value("message_id", ""), "program_not_a_file");

    ProcessResult trace = sim({"run", "p.nc", "--trace", "nodir/t.jsonl", "--lang", "zh_CN"});
    EXPECT_EQ(trace.exitStatus, kExitError);
    EXPECT_SAYS(trace, "nodir/t.jsonl: 无法写入跟踪文件：");
    j = output(trace);
    EXPECT_EQ(j["alarm"].value("message_id", ""), "trace_cannot_write") << j;
    EXPECT_EQ(j["alarm"].value("message", "").rfind("cannot write the trace file: ", 0), 0u) << j;
}

TEST_F(CliFileWordsTest, WhereTheExternalOutputWentIsSaidInTheLanguage) {
    write("out.nc", "POPEN\nDPRNT[HELLO]\nPCLOS\nM30\n");
    auto [english, chinese] = both({"run", "out.nc", "--dialect", "fanuc"});
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_SAYS(english, "m350-sim: external output (POPEN/DPRNT/PCLOS) written to ");
    EXPECT_SAYS(chinese, "m350-sim: 外部输出(POPEN/DPRNT/PCLOS)已写入");
}

TEST_F(CliFileWordsTest, ToolTableAndToolLifeLinesSkippedAreSaidInTheLanguage) {
    write("t.tbl", "T1 P1 Z-5\nT0 P2\nT3 P1\n");
    auto [english, chinese] = both({"run", "p.nc", "--tool-table", "t.tbl"});
    EXPECT_SAYS(english, "t.tbl:2:1: error: 'T0': tool numbers start at 1 (T0 is the empty spindle) (line skipped)");
    EXPECT_SAYS(chinese, "t.tbl:2:1: 错误：'T0'：刀号从1开始（T0为主轴无刀）（该行已跳过）");
    EXPECT_SAYS(chinese, "t.tbl:3:1: 错误：刀位1已有刀具（第1行）：刀位号不能重复（该行已跳过）");
    ProcessResult tools = sim({"tools", "--tool-table", "t.tbl"});
    json j = output(tools);
    ASSERT_EQ(j["issues"].size(), 2u) << j;
    EXPECT_EQ(j["issues"][0].value("message_id", ""), "tool_table_tool_from_1") << j;
    EXPECT_EQ(j["issues"][1].value("message_id", ""), "tool_table_pocket_twice") << j;

    write("m350/toollife.txt", "gs 3\ngroup 1 life 2 hours\ngroup 2 life 5 count\n");
    auto [lifeEnglish, lifeChinese] = both({"run", "p.nc", "--config", "m350"});
    EXPECT_SAYS(lifeEnglish, "toollife.txt:2:16: error: the life is counted in 'count' or 'minutes', not 'hours' (line skipped)");
    EXPECT_SAYS(lifeChinese, "toollife.txt:2:16: 错误：寿命按'count'（次数）或'minutes'（分钟）计，不能为'hours'（该行已跳过）");
    EXPECT_SAYS(lifeChinese, "toollife.txt:3:1: 错误：刀具组2没有刀具（该行已跳过）");
    j = output(lifeChinese);
    ASSERT_EQ(j["tool_life"]["issues"].size(), 2u) << j;
    EXPECT_EQ(j["tool_life"]["issues"][0].value("message_id", ""), "life_file_kind");
    EXPECT_EQ(j["tool_life"]["issues"][0].value("message", ""), "the life is counted in 'count' or 'minutes', not 'hours'");
    EXPECT_EQ(j["tool_life"]["issues"][1].value("message_id", ""), "life_file_group_no_tools");
}

// The capacity of a tool life group (GS1/GS2) is a message of the table too: said in Chinese.
TEST_F(CliFileWordsTest, AToolLifeGroupBeyondTheCapacityIsSaidInTheLanguage) {
    write("m350/toollife.txt", "gs 3\ngroup 1 life 2 count\ntool 1 h 0 d 0 used 0\ntool 2 h 0 d 0 used 0\n"
                               "tool 3 h 0 d 0 used 0\n");
    ProcessResult r = sim({"run", "p.nc", "--config", "m350", "--lang", "zh_CN"});
    json j = output(r);
    ASSERT_EQ(j["tool_life"]["issues"].size(), 1u) << j;
    const std::string id = j["tool_life"]["issues"][0].value("message_id", "");
    ASSERT_FALSE(id.empty()) << j;
    EXPECT_EQ(r.err.find("(line skipped)"), std::string::npos) << r.err;
    EXPECT_SAYS(r, "toollife.txt:2:1: 错误：");
}

TEST_F(CliFileWordsTest, AParameterValueThePanelWouldRefuseIsWarnedInTheLanguage) {
    auto [english, chinese] = both({"run", "p.nc", "--param", "129=120"});
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_SAYS(english, "m350-sim: warning: --param 129=120: parameter 129 (Floating tool set thickness) must be from 0 "
                         "to 99, not 120 (used as given)");
    EXPECT_SAYS(chinese, "m350-sim: 警告：--param 129=120：参数129（浮动对刀仪厚度）须在0到99之间，不能为120（按给定的值使用）");

    std::string params = read("m350/params.toml");
    const std::size_t at = params.find("\n129 = ");
    ASSERT_NE(at, std::string::npos);
    params.replace(at + 1, params.find('\n', at + 1) - at - 1, "129 = 120");
    write("m350/params.toml", params);
    auto [folderEnglish, folderChinese] = both({"run", "p.nc", "--config", "m350"});
    EXPECT_SAYS(folderEnglish, "params.toml: warning: parameter 129 (Floating tool set thickness) must be from 0 to 99, not "
                               "120 (used as written)");
    EXPECT_SAYS(folderChinese, "params.toml: 警告：参数129（浮动对刀仪厚度）须在0到99之间，不能为120（按写入的值使用）");
}

TEST_F(CliFileWordsTest, AnOutputFileItCannotWriteIsSaidInTheLanguage) {
    fs::create_directory(dir_ / "shots");
    auto [english, chinese] = both({"run", "p.nc", "--trace", "shots"});
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "shots: cannot write the trace file: shots: cannot write: it is a folder");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "shots: 无法写入跟踪文件：shots：无法写入：这是一个文件夹");
    ProcessResult tools = sim({"run", "p.nc", "--tools-out", "shots", "--lang", "zh_CN"});
    EXPECT_SAYS(tools, "m350-sim: --tools-out: shots：无法写入：这是一个文件夹");
}

} // namespace m350::clitest
