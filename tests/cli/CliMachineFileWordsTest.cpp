// The reasons a machine folder's file is refused with (the file reader's: a FIFO, a device, too
// big; toollife.txt's; spindle-load.toml's; [variables] common's) are said by message id inside
// the load error: with --lang zh_CN the whole line is Chinese, with --lang en it is the English it
// always was, at the file (and line:column where there is one).
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <sys/stat.h>

namespace m350::clitest {

namespace {

class CliMachineFileWordsTest : public CliTest {
  protected:
    fs::path copy(const char* machine) {
        const fs::path folder = dir_ / "machine";
        fs::copy(fs::path(M350_MACHINES_DIR) / machine, folder, fs::copy_options::recursive);
        return folder;
    }

    std::pair<ProcessResult, ProcessResult> both() {
        return {sim({"mdi", "G4 P1", "--config", "machine", "--lang", "en"}),
                sim({"mdi", "G4 P1", "--config", "machine", "--lang", "zh_CN"})};
    }
};

#define EXPECT_SAYS(result, text) EXPECT_NE((result).err.find(text), std::string::npos) << (result).err

// No English word of four letters or more is left in the Chinese error line (the file's name and
// FIFO, which the Chinese panel says too, aside).
void expectNoEnglishWords(const std::string& err, const std::string& fileName) {
    std::string line = err.substr(0, err.find('\n'));
    for (const std::string& kept : {fileName, std::string("FIFO")}) {
        for (std::size_t at; (at = line.find(kept)) != std::string::npos;) {
            line.erase(at, kept.size());
        }
    }
    int run = 0;
    for (char c : line) {
        run = std::isalpha(static_cast<unsigned char>(c)) ? run + 1 : 0;
        EXPECT_LT(run, 4) << line;
    }
}

} // namespace

TEST_F(CliMachineFileWordsTest, AFifoAsToolTableIsRefusedInChinese) {
    const fs::path folder = copy("m350-linear16");
    ASSERT_EQ(::mkfifo((folder / "tool.tbl").c_str(), 0600), 0);
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "machine/tool.tbl: cannot read the tool table: it is a FIFO (named pipe), not a regular file");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "machine/tool.tbl: 无法读取刀具表：这是 FIFO（命名管道），不是正规文件");
    expectNoEnglishWords(chinese.err, "machine/tool.tbl");
    json j = output(chinese);
    EXPECT_EQ(j["alarm"].value("message", ""), "cannot read the tool table: it is a FIFO (named pipe), not a regular file")
        << j;
}

TEST_F(CliMachineFileWordsTest, AFifoOrAFolderAsToolLifeFileIsRefusedInChinese) {
    const fs::path folder = copy("m350-linear16");
    ASSERT_EQ(::mkfifo((folder / "toollife.txt").c_str(), 0600), 0);
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "machine/toollife.txt: cannot read the file: it is a FIFO (named pipe), not a regular file");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "machine/toollife.txt: 刀具寿命文件：无法读取文件：这是 FIFO（命名管道），不是正规文件");
    expectNoEnglishWords(chinese.err, "machine/toollife.txt");

    fs::remove(folder / "toollife.txt");
    fs::create_directory(folder / "toollife.txt");
    ProcessResult dir = sim({"mdi", "G4 P1", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_SAYS(dir, "machine/toollife.txt: 刀具寿命文件：无法读取文件：这是文件夹，不是正规文件");
}

TEST_F(CliMachineFileWordsTest, AnUnreadableSpindleLoadFileIsRefusedInChinese) {
    const fs::path folder = copy("m350-linear16");
    fs::create_directory(folder / "spindle-load.toml");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "machine/spindle-load.toml:1:1: cannot read: it is a folder, not a regular file");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "machine/spindle-load.toml:1:1: 主轴负载监视设置有误：无法读取：这是文件夹，不是正规文件");
    expectNoEnglishWords(chinese.err, "machine/spindle-load.toml");

    fs::remove(folder / "spindle-load.toml");
    std::ofstream(folder / "spindle-load.toml") << "[monitor]\nsample_ms = 0\n";
    auto [badEnglish, badChinese] = both();
    EXPECT_SAYS(badEnglish, "machine/spindle-load.toml:2:13: sample_ms must be a number from 1 to 10000");
    EXPECT_SAYS(badChinese, "machine/spindle-load.toml:2:13: 主轴负载监视设置有误：sample_ms 须为 1 到 10000 之间的数");

    std::ofstream(folder / "spindle-load.toml", std::ios::trunc) << "[monitor]\n\n[tool.3]\nlower = 90\nupper = 50\n";
    auto [orderEnglish, orderChinese] = both();
    EXPECT_SAYS(orderEnglish, "machine/spindle-load.toml:3:1: tool 3: need 0 <= lower < upper (upper 0: none)");
    EXPECT_SAYS(orderChinese, "machine/spindle-load.toml:3:1: 主轴负载监视设置有误：刀具 3：须满足 0 <= lower < upper");
}

TEST_F(CliMachineFileWordsTest, ABadCommonRangeIsRefusedInChineseAtItsPlace) {
    const fs::path folder = copy("fanuc-0i");
    std::string text;
    {
        std::ifstream in(folder / "machine.toml", std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto lines = std::count(text.begin(), text.end(), '\n');
    std::ofstream(folder / "machine.toml", std::ios::binary) << text << "\n[variables]\ncommon = [\"100-1500\"]\n";
    const std::string where = "machine/machine.toml:" + std::to_string(lines + 3) + ":11: ";
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, where + "[variables] common: #100-#1500 is not a common variable range: they lie within "
                                 "#100-#999 or #20000-#999999 (the numbers between are system variables)");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, where + "[variables] common 有误：#100-#1500 不是公共变量范围：公共变量位于 #100-#999 或 "
                                 "#20000-#999999 之内（其间的编号是系统变量）");
    expectNoEnglishWords(chinese.err.substr(chinese.err.find(where)), where + "[variables] common");

    std::ofstream(folder / "machine.toml", std::ios::binary | std::ios::trunc)
        << text << "\n[variables]\ncommon = [\"100-499\", \"400-600\"]\n";
    ProcessResult overlap = sim({"mdi", "G4 P1", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_SAYS(overlap, "[variables] common 有误：#100-#499 与 #400-#600 重叠");
}

// modbus.toml that cannot be read is said as that, not as a TOML syntax error.
TEST_F(CliMachineFileWordsTest, AnUnreadableModbusFileIsNoSyntaxError) {
    const fs::path folder = copy("m350-linear16");
    fs::create_directory(folder / "modbus.toml");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "1:1: cannot read: it is a folder, not a regular file");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "1:1：无法读取：这是文件夹，不是正规文件");
    EXPECT_EQ(chinese.err.find("TOML"), std::string::npos) << chinese.err;
}

// A save.journal a crash left that cannot be finished stops the load, said in the language.
TEST_F(CliMachineFileWordsTest, ABrokenChangeJournalIsSaidInChinese) {
    const fs::path folder = copy("m350-linear16");
    std::ofstream(folder / "save.journal") << "hello\n";
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "save.journal: not a change journal of m350 (remove it to keep the files as they are)");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "中断的保存未能完成：");
    EXPECT_SAYS(chinese, "save.journal：不是本仿真器的修改日志（删除该日志即可保留文件现状）");
    expectNoEnglishWords(chinese.err, "machine/save.journal");

    fs::remove(folder / "save.journal");
    fs::create_directory(folder / "save.journal");
    ProcessResult dir = sim({"mdi", "G4 P1", "--config", "machine", "--lang", "zh_CN"});
    EXPECT_SAYS(dir, "save.journal：无法读取中断保存的修改日志：这是文件夹，不是正规文件");
}

} // namespace m350::clitest
