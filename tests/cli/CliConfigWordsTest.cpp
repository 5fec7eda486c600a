// What m350-sim says about a machine folder it loads (a key nobody reads, a TOML file it cannot
// parse, a value it refuses, a FANUC's section on an M350, a tool.tbl Z that differs from the
// parameter) is said by message id: with --lang zh_CN in Chinese, without it in English, always
// with the file:line:col, and the JSON keeps the English with the message_id.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace m350::clitest {

namespace {

class CliConfigWordsTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::copy(fs::path(M350_MACHINES_DIR) / "m350-linear16", dir_ / "m350", fs::copy_options::recursive);
    }

    void append(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / "m350" / name, std::ios::app) << text;
    }

    void prepend(const std::string& name, const std::string& text) {
        std::ifstream in(dir_ / "m350" / name, std::ios::binary);
        const std::string was{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        replace(name, text + was);
    }

    void replace(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / "m350" / name, std::ios::trunc) << text;
    }

    std::pair<ProcessResult, ProcessResult> both() {
        return {sim({"mdi", "G4 P1", "--config", "m350", "--lang", "en"}),
                sim({"mdi", "G4 P1", "--config", "m350", "--lang", "zh_CN"})};
    }
};

#define EXPECT_SAYS(result, text) EXPECT_NE((result).err.find(text), std::string::npos) << (result).err

} // namespace

TEST_F(CliConfigWordsTest, AnUnknownKeyIsAWarningInTheLanguageAtItsPlace) {
    prepend("machine.toml", "nmae = \"typo\"\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitOk) << english.err;
    EXPECT_SAYS(english, "m350/machine.toml:1:1: warning: unknown key 'nmae' (ignored; a typo?)");
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_SAYS(chinese, "m350/machine.toml:1:1: 警告：未知的键'nmae'（已忽略；是否拼写有误？）");
    EXPECT_EQ(chinese.err.find("warning"), std::string::npos) << chinese.err;
}

TEST_F(CliConfigWordsTest, BadTomlIsAConfigErrorAtLineAndColumnInTheLanguage) {
    replace("params.toml", "[params]\n61 = 3000\n62 = = 500\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "m350/params.toml:3:6: Error while parsing value");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "m350/params.toml:3:6: TOML 语法错误：");

    replace("params.toml", "[params]\n61 = \"fast\"\n");
    auto [wrongEnglish, wrongChinese] = both();
    EXPECT_SAYS(wrongEnglish, "m350/params.toml:2:6: '61' must be a number");
    EXPECT_SAYS(wrongChinese, "m350/params.toml:2:6: '61'须为数值");
    json j = output(wrongChinese);
    EXPECT_EQ(j["alarm"].value("code", ""), "config_error") << j;
    EXPECT_EQ(j["alarm"].value("message", ""), "'61' must be a number") << j;
    EXPECT_EQ(j["alarm"].value("message_id", ""), "config_must_be_number") << j;

    replace("params.toml", "[params]\n5000 = 1\n");
    auto [keyEnglish, keyChinese] = both();
    EXPECT_SAYS(keyEnglish, "m350/params.toml:2:1: parameter '5000' is not a number from 0 to 999");
    EXPECT_SAYS(keyChinese, "m350/params.toml:2:1: 参数'5000'不是0到999之间的数");
}

TEST_F(CliConfigWordsTest, AMagazineValueItRefusesIsSaidInTheLanguage) {
    replace("machine.toml", "name = \"t\"\n[magazine]\ndevice = \"carousel\"\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "m350/machine.toml: [magazine] device must be \"linear-rack\" or \"servo-disc\" or "
                         "\"umbrella\" or \"multi-head\", not 'carousel'");
    EXPECT_SAYS(chinese, "m350/machine.toml: [magazine] device须为\"linear-rack\"或\"servo-disc\"或\"umbrella\"或"
                         "\"multi-head\"，不能为'carousel'");
}

TEST_F(CliConfigWordsTest, InterfaceSignalsOnAnM350AreIgnoredWithAWarningInTheLanguage) {
    append("machine.toml", "\n[interface_signals]\nUI000 = \"IN05\"\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitOk) << english.err;
    EXPECT_SAYS(english, "m350/machine.toml:44:1: warning: [interface_signals] are a FANUC's (#1000-#1133): this "
                         "M350 machine ignores them");
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_SAYS(chinese, "m350/machine.toml:44:1: 警告：[interface_signals] 是 FANUC 的接口信号（#1000-#1133）：本 M350 "
                         "机床不使用，已忽略");
}

TEST_F(CliConfigWordsTest, AToolTableZThatDiffersFromTheParameterIsSaidInTheLanguage) {
    replace("tool.tbl", "T1 P1 Z-20 ;reference\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitOk) << english.err;
    EXPECT_SAYS(english, "m350/params.toml: warning: parameter 930 (T1 Z) is -53.677 but m350/tool.tbl:1 says -20; "
                         "the tool table is used");
    EXPECT_EQ(chinese.exitStatus, kExitOk) << chinese.err;
    EXPECT_SAYS(chinese, "m350/params.toml: 警告：参数930（T1 Z）为-53.677，但m350/tool.tbl:1中为-20；以刀具表为准");
}

TEST_F(CliConfigWordsTest, AModbusTableItRefusesIsSaidInTheLanguage) {
    replace("modbus.toml", "[slave.1.holding]\n8192 = 70000\n");
    auto [english, chinese] = both();
    EXPECT_EQ(english.exitStatus, kExitError);
    EXPECT_SAYS(english, "m350/modbus.toml: line 2: slave 1 holding '8192': addresses are 0-65535 and values whole "
                         "numbers from -32768 to 65535");
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "m350/modbus.toml: 第2行：从站1 holding '8192'：地址为 0-65535，数值须为 -32768 到 65535 的整数");
}

TEST_F(CliConfigWordsTest, AFolderThatIsNotThereIsSaidInTheLanguage) {
    ProcessResult chinese = sim({"mdi", "G4 P1", "--config", "nowhere", "--lang", "zh_CN"});
    EXPECT_EQ(chinese.exitStatus, kExitError);
    EXPECT_SAYS(chinese, "nowhere: 不是机床文件夹（目录不存在）");
}

} // namespace m350::clitest
