// m350-sim import, as an owner with a copy of their controller's system disk runs it: the machine
// folder it makes loads, runs its MDI lines and its T.nc, and gives the #-variables the binary
// files hold; a damaged backup and a folder that is not this import's are refused, nothing written.
#include "tests/cli/CliFixture.h"
#include "tests/support/ControllerBackupWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

#include <sys/stat.h>

namespace m350::clitest {

using m350::testing::ControllerBackupWriter;

namespace {

std::vector<std::string> folderFiles(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.is_regular_file()) {
            names.push_back(fs::relative(entry.path(), folder).generic_string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

class CliImportTest : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        backup_ = ControllerBackupWriter::smallRouter();
        backup_.writeTo(dir_ / "SYSDISK");
    }
    ProcessResult import(const std::string& into) { return sim({"import", "SYSDISK", "--into", into}); }

    ControllerBackupWriter backup_;
};

TEST_F(CliImportTest, TheImportedMachineRunsItsMdiLinesAndTNcWithTheBackupsVariables) {
    ProcessResult r = import("machine");
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "ok");
    EXPECT_TRUE(j["alarm"].is_null());
    EXPECT_NE(r.err.find("magazine type 4 (servo disc"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("The simulator cannot model:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("To review in machine.toml"), std::string::npos) << r.err;

    // the MDI lines as the JSON gives them (UTF-8), run as the MDI page runs them
    std::vector<std::string> args{"mdi"};
    for (const json& line : j["mdi_lines"]) {
        if (!line.get<std::string>().empty()) {
            args.push_back(line);
        }
    }
    ASSERT_EQ(args.size(), 5u) << j["mdi_lines"];
    EXPECT_EQ(args[4], "(MDI 测试)");
    for (const char* option : {"--config", "machine", "--print", "150,1300"}) {
        args.emplace_back(option);
    }
    ProcessResult mdi = sim(args);
    ASSERT_EQ(mdi.exitStatus, kExitOk) << mdi.err;
    json m = output(mdi);
    EXPECT_EQ(m["vars"]["150"], backup_.setting[129] + 1);
    EXPECT_EQ(m["machine"]["X"], backup_.coordinate[5] + 20);
    EXPECT_EQ(m["machine"]["Y"], backup_.coordinate[6] + 10);

    // T.nc (T#1504), run as the panel runs it for a T word, calls the backup's O20000
    ProcessResult t = sim({"hook", "T", "--config", "machine", "--var", "1504=5", "--print",
                           "629,1300,1302,1306,805,806,807,811,812,842"});
    ASSERT_EQ(t.exitStatus, kExitOk) << t.err;
    json v = output(t)["vars"];
    EXPECT_EQ(v["629"], backup_.setting[129]);
    EXPECT_EQ(v["1300"], 5);
    EXPECT_EQ(v["1302"], backup_.setting[802]);
    EXPECT_EQ(v["1306"], backup_.setting[806]);
    EXPECT_EQ(v["805"], backup_.coordinate[5]);
    EXPECT_EQ(v["806"], backup_.coordinate[6]);
    EXPECT_EQ(v["807"], backup_.coordinate[7]);
    EXPECT_EQ(v["842"], backup_.coordinate[42]);
    EXPECT_EQ(output(t)["machine"]["Z"], backup_.setting[806]); // O20000's G53 Z#1306

    // with no T, the current tool is the backup's param 800
    json start = output(sim({"mdi", "G4 P1", "--config", "machine", "--print", "1300,1301"}));
    EXPECT_EQ(start["vars"]["1300"], backup_.setting[800]);
    EXPECT_EQ(start["vars"]["1301"], backup_.setting[801]);
}

TEST_F(CliImportTest, WithoutAMagazineDeviceTheMachineStillHomesJogsAndProbesItsToolsWhereTheyWereSet) {
    ASSERT_EQ(import("machine").exitStatus, kExitOk);
    ProcessResult home = sim({"mdi", "G91 G0 X5 Y-5", "--config", "machine", "--unhomed", "--home", "--print",
                              "1515,1516,1517"});
    ASSERT_EQ(home.exitStatus, kExitOk) << home.err;
    json h = output(home);
    for (const char* flag : {"1515", "1516", "1517"}) {
        EXPECT_EQ(h["vars"][flag], 1) << flag;
    }
    // the stated tool lengths and setter top give back the Z offset the controller stored for T2
    ProcessResult probe = sim({"mdi", "#1502=2", "M98 P502", "--config", "machine", "--print", "1431,1927"});
    ASSERT_EQ(probe.exitStatus, kExitOk) << probe.err;
    json p = output(probe);
    EXPECT_NEAR(p["vars"]["1431"].get<double>(), backup_.setting[931], 1e-9) << p;
    EXPECT_NEAR(p["machine"]["Z"].get<double>(), backup_.setting[931] + backup_.setting[140], 1e-9) << p;
}

TEST_F(CliImportTest, TheResultListsWhatWasWrittenCopiedAndSkipped) {
    json j = output(import("machine"));
    EXPECT_EQ(j["machine_folder"], (dir_ / "machine").string());
    EXPECT_EQ(j["copied"], json({"T.nc", "cam/cam1.nc", "pause.nc", "slib-g.nc", "slib-m.nc"}));
    EXPECT_EQ(j["libraries"], json({"slib-g.nc", "slib-m.nc"}));
    ASSERT_EQ(j["hooks"].size(), 2u) << j["hooks"];
    EXPECT_EQ(j["hooks"][0].get<std::string>().rfind("T.nc: a T word", 0), 0u) << j["hooks"];
    EXPECT_EQ(j["hooks"][1].get<std::string>().rfind("pause.nc: ", 0), 0u) << j["hooks"];
    std::set<std::string> skipped;
    for (const json& s : j["skipped"]) {
        skipped.insert(s["file"].get<std::string>());
        EXPECT_FALSE(s["reason"].get<std::string>().empty()) << s;
    }
    EXPECT_EQ(skipped, (std::set<std::string>{"cam/cam1.bmp", "ddcs", "drivers/m350io.ko", "eng", "logo.bmp",
                                              "simsun.ttf", "sys.log"}));
    EXPECT_EQ(j["parameters"], 1000);
    EXPECT_EQ(j["unchanged"], false);
    EXPECT_TRUE(j["diagnostics"].empty()) << j["diagnostics"];
    std::vector<std::string> written = j["written"];
    std::sort(written.begin(), written.end());
    EXPECT_EQ(written, folderFiles(dir_ / "machine"));
    EXPECT_EQ(m350::testing::readFile(dir_ / "machine/pause.nc"), backup_.files["pause.nc"]); // GBK stays GBK
    EXPECT_EQ(m350::testing::readFile(dir_ / "machine/cam/cam1.nc"), "G0 X0 Y0\r\n");
}

// The numbers the import works out (the setters' tops, the tool lengths) are written at the
// parameters' four decimals: no float noise such as -118.67699999999999 in machine.toml or the report.
TEST_F(CliImportTest, WorkedOutNumbersAreWrittenAtFourDecimals) {
    backup_.setting[930] = -20.0; // T1's and T2's Z offsets as taught: T2's length works out
    backup_.setting[931] = -31.4; // as -31.4 - (-31.4 - 60), 60.00000000000001 in doubles
    backup_.writeTo(dir_ / "SYSDISK");
    ProcessResult r = import("machine");
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    const std::string toml = m350::testing::readFile(dir_ / "machine/machine.toml");
    const std::regex noisy(R"(\d\.\d{5,})");
    std::smatch found;
    EXPECT_FALSE(std::regex_search(toml, found, noisy)) << found.str(0) << "\n" << toml;
    EXPECT_FALSE(std::regex_search(r.err, found, noisy)) << found.str(0) << "\n" << r.err;
    EXPECT_NE(toml.find("[tool_setter]\ntop = "), std::string::npos) << toml;
}

TEST_F(CliImportTest, ImportingTwiceGivesTheSameFolderAndASecondRunIntoItChangesNothing) {
    ASSERT_EQ(import("first").exitStatus, kExitOk);
    ASSERT_EQ(import("second").exitStatus, kExitOk);
    ASSERT_EQ(folderFiles(dir_ / "first"), folderFiles(dir_ / "second"));
    for (const std::string& name : folderFiles(dir_ / "first")) {
        EXPECT_EQ(m350::testing::readFile(dir_ / "first" / name), m350::testing::readFile(dir_ / "second" / name))
            << name;
    }
    ProcessResult again = import("first");
    EXPECT_EQ(again.exitStatus, kExitOk) << again.err;
    EXPECT_EQ(output(again)["unchanged"], true);
    EXPECT_NE(again.err.find("nothing written"), std::string::npos) << again.err;
}

TEST_F(CliImportTest, AFolderHoldingSomethingElseIsRefusedAndLeftAlone) {
    write("mine/params.toml", "[params]\n61 = 1\n");
    ProcessResult r = import("mine");
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "error");
    EXPECT_EQ(j["alarm"]["code"], "machine_folder_not_empty");
    EXPECT_NE(r.err.find("mine: is not empty"), std::string::npos) << r.err;
    EXPECT_EQ(folderFiles(dir_ / "mine"), std::vector<std::string>{"params.toml"});
    EXPECT_EQ(m350::testing::readFile(dir_ / "mine/params.toml"), "[params]\n61 = 1\n");
}

TEST_F(CliImportTest, ATruncatedSettingIsRefusedNamingTheFileAndNothingIsWritten) {
    std::string setting = m350::testing::readFile(dir_ / "SYSDISK/setting");
    write("SYSDISK/setting", setting.substr(0, 7992));
    ProcessResult r = import("machine");
    EXPECT_EQ(r.exitStatus, kExitError);
    json j = output(r);
    EXPECT_EQ(j["alarm"]["code"], "backup_error");
    EXPECT_EQ(j["alarm"]["file"], "SYSDISK/setting");
    EXPECT_NE(r.err.find("SYSDISK/setting: holds 7992 bytes"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("parameter 999"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "machine"));
    EXPECT_EQ(folderFiles(dir_).size(), folderFiles(dir_ / "SYSDISK").size()); // no temp folder left
}

TEST_F(CliImportTest, ANanInSettingIsRefusedNamingItsOffsetAndParameter) {
    backup_.setting[129] = std::nan("");
    backup_.writeTo(dir_ / "SYSDISK");
    ProcessResult r = import("machine");
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find("SYSDISK/setting: offset 1032, parameter 129 (浮动对刀仪厚度"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nan"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "machine"));
}

// With --lang zh_CN the import's refusals and its result are said in Chinese (message ids); the
// JSON keeps the English with the message_id.
TEST_F(CliImportTest, TheImportSpeaksTheLanguageAsked) {
    backup_.setting[129] = std::nan("");
    backup_.writeTo(dir_ / "SYSDISK");
    ProcessResult nan = sim({"import", "SYSDISK", "--into", "machine", "--lang", "zh_CN"});
    EXPECT_EQ(nan.exitStatus, kExitError);
    EXPECT_NE(nan.err.find("SYSDISK/setting: 偏移1032处，参数129（浮动对刀仪厚度）：该值为 NaN；文件已损坏，未导入任何内容"),
              std::string::npos)
        << nan.err;
    json j = output(nan);
    EXPECT_EQ(j["alarm"].value("message_id", ""), "backup_damaged") << j;
    EXPECT_NE(j["alarm"].value("message", "").find("the file is damaged, nothing imported"), std::string::npos) << j;

    write("mine/params.toml", "[params]\n61 = 1\n");
    backup_.setting[129] = 10.0;
    backup_.writeTo(dir_ / "SYSDISK");
    ProcessResult full = sim({"import", "SYSDISK", "--into", "mine", "--lang", "zh_CN"});
    EXPECT_EQ(full.exitStatus, kExitError);
    EXPECT_NE(full.err.find("mine: 不是空文件夹，其中也不是此备份的导入结果（缺少machine.toml，params.toml内容不同，"), std::string::npos)
        << full.err;
    ProcessResult done = sim({"import", "SYSDISK", "--into", "machine", "--lang", "zh_CN"});
    EXPECT_EQ(done.exitStatus, kExitOk) << done.err;
    EXPECT_NE(done.err.find("已将SYSDISK导入"), std::string::npos) << done.err;
    ProcessResult missing = sim({"import", "nowhere", "--into", "other", "--lang", "zh_CN"});
    EXPECT_NE(missing.err.find("nowhere: 不是文件夹：控制器备份是存放 `setting`、slib-g.nc 等文件的文件夹"), std::string::npos)
        << missing.err;
}

namespace {

bool isChinese(unsigned char lead) { return lead >= 0xE4 && lead <= 0xE9; }

// The Latin words of 4+ letters a Chinese report says, leaving out what it names as the files and
// the controller have them: a token holding . / _ = " [ or # (file names, paths, machine.toml keys
// and values, G-code), the backup's own file names without an extension, the folder named on the
// command line, and RTCP (in the catalogue's Chinese name of param 31, as the controller says it).
std::set<std::string> englishWords(const std::string& text, const std::string& folder = "") {
    static const std::regex token(R"re([\x21-\x7e]+)re"); // a run of printable ASCII, no space
    static const std::regex word("[A-Za-z]{4,}");
    static const std::set<std::string> names{"setting", "coordinate", "mdiblock", "ddcs", "loading", "opening", "device", "RTCP"};
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), token); it != std::sregex_iterator(); ++it) {
        const std::string t = it->str();
        if (t.find_first_of("./_=\"[#") != std::string::npos) {
            continue;
        }
        for (auto w = std::sregex_iterator(t.begin(), t.end(), word); w != std::sregex_iterator(); ++w) {
            if (names.count(w->str()) == 0 && w->str() != folder) {
                found.insert(w->str());
            }
        }
    }
    return found;
}

// The report's lines that hold a Chinese character, once the controller's own names for what the
// English says beside them are left out (the magazine types, a hook's 回机械原点).
std::vector<std::string> chineseLines(std::string text) {
    for (const std::string name : {"无刀库", "多工序", "龙门架直排", "固定直排", "圆盘刀库", "回机械原点", "回工件原点", "回零"}) {
        for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name)) {
            text.erase(at, name.size());
        }
    }
    std::vector<std::string> found;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (std::any_of(line.begin(), line.end(), [](char c) { return isChinese(static_cast<unsigned char>(c)); })) {
            found.push_back(line);
        }
    }
    return found;
}

} // namespace

// The report `m350-sim import` prints and the import-report.txt it writes are in --lang, wholly:
// titles, the magazine, skipped files, review items, what cannot be modelled, syntax errors and
// notes; the file's first line says its language. The JSON keeps its English texts and codes. A
// second import into the folder in the other language finds it unchanged (the report is the same
// import's) and leaves the report as it was.
TEST_F(CliImportTest, TheReportAndImportReportTxtAreWhollyInTheLanguageAsked) {
    backup_.files["key-1.nc"] = "G01 X\nM99\n"; // a syntax error the report lists
    backup_.writeTo(dir_ / "SYSDISK");
    fs::remove(dir_ / "SYSDISK/coordinate"); // a note
    ControllerBackupWriter gantry = ControllerBackupWriter::dualYGantry(); // a gantry motor, a value out of range
    gantry.writeTo(dir_ / "GANTRY");

    for (const auto& [from, into] : {std::pair{"SYSDISK", "zh"}, std::pair{"GANTRY", "zh-gantry"}}) {
        SCOPED_TRACE(from);
        ProcessResult zh = sim({"import", from, "--into", into, "--lang", "zh_CN"});
        ASSERT_EQ(zh.exitStatus, kExitOk) << zh.err;
        const std::string report = m350::testing::readFile(dir_ / into / "import-report.txt");
        EXPECT_EQ(report.substr(0, report.find('\n')), "由控制器备份生成的机器文件夹（本报告为中文）");
        EXPECT_NE(zh.err.find(report), std::string::npos) << "the printed report is the file's:\n" << zh.err;
        EXPECT_EQ(englishWords(zh.err, from), std::set<std::string>{}) << zh.err;
        EXPECT_NE(report.find("仿真无法模拟："), std::string::npos) << report;
        json j = output(zh);
        EXPECT_EQ(j["magazine"].get<std::string>().rfind("magazine type ", 0), 0u) << "the JSON keeps the English: " << j;
        for (const json& skipped : j["skipped"]) {
            EXPECT_EQ(chineseLines(skipped.value("reason", "")), std::vector<std::string>{}) << skipped;
        }
    }
    const std::string router = m350::testing::readFile(dir_ / "zh/import-report.txt");
    EXPECT_NE(router.find("  刀库类型4（圆盘刀库），容量6：未建模，无刀库装置\n"), std::string::npos) << router;
    EXPECT_NE(router.find("未复制（仿真不使用的7个文件）：\n"), std::string::npos) << router;
    EXPECT_NE(router.find("  logo.bmp：图片（面板自行绘制画面）\n"), std::string::npos) << router;
    EXPECT_NE(router.find("须在machine.toml中核对"), std::string::npos) << router;
    EXPECT_NE(router.find("仿真尚不接受的语法"), std::string::npos) << router;
    EXPECT_NE(router.find("key-1.nc:1:"), std::string::npos) << router;
    EXPECT_NE(router.find("备注：\n  没有coordinate文件：所有工件坐标偏置为0\n"), std::string::npos) << router;
    const std::string gantryReport = m350::testing::readFile(dir_ / "zh-gantry/import-report.txt");
    EXPECT_NE(gantryReport.find("：龙门的第二个电机。"), std::string::npos) << gantryReport;
    EXPECT_NE(gantryReport.find("面板会拒绝的参数值（按控制器原值保留）：\n"), std::string::npos) << gantryReport;
    EXPECT_NE(gantryReport.find("\n  参数969（T3主轴速度）须为100到200的整数，不能为0\n"), std::string::npos) << gantryReport;

    for (const auto& [from, into] : {std::pair{"SYSDISK", "en"}, std::pair{"GANTRY", "en-gantry"}}) {
        SCOPED_TRACE(from);
        ProcessResult en = sim({"import", from, "--into", into, "--lang", "en"});
        ASSERT_EQ(en.exitStatus, kExitOk) << en.err;
        const std::string report = m350::testing::readFile(dir_ / into / "import-report.txt");
        EXPECT_EQ(report.substr(0, report.find('\n')), "Machine folder from a controller backup (this report in English)");
        EXPECT_NE(en.err.find(report), std::string::npos) << en.err;
        EXPECT_EQ(chineseLines(report), std::vector<std::string>{}) << report;
        EXPECT_NE(report.find("The simulator cannot model:"), std::string::npos) << report;
    }
    EXPECT_NE(m350::testing::readFile(dir_ / "en/import-report.txt").find("  logo.bmp: image (the panel draws its own screens)\n"),
              std::string::npos);

    // the same import in the other language: this import all the same, nothing rewritten
    ProcessResult again = sim({"import", "SYSDISK", "--into", "zh", "--lang", "en"});
    ASSERT_EQ(again.exitStatus, kExitOk) << again.err;
    EXPECT_EQ(output(again)["unchanged"], true);
    EXPECT_EQ(m350::testing::readFile(dir_ / "zh/import-report.txt"), router);
}

// Issue 26: a `coordinate` or `setting` that is a folder or a link to a device was "not found" or
// gave "every work offset is 0"; each is said as what it is (a device refused unread).
TEST_F(CliImportTest, ADataFileThatIsAFolderFifoOrDeviceIsSaidAsWhatItIs) {
    for (const char* name : {"coordinate", "setting"}) {
        const fs::path file = dir_ / "SYSDISK" / name;
        const std::string bytes = m350::testing::readFile(file);
        struct Case {
            const char* says;
            void (*make)(const fs::path&);
        };
        const Case cases[] = {
            {"it is a folder, not a regular file", [](const fs::path& f) { fs::create_directory(f); }},
            {"it is a device, not a regular file", [](const fs::path& f) { fs::create_symlink("/dev/zero", f); }},
            {"it is a FIFO (named pipe), not a regular file", [](const fs::path& f) { ::mkfifo(f.c_str(), 0600); }},
        };
        for (const Case& c : cases) {
            fs::remove_all(file);
            c.make(file);
            ProcessResult r = import("machine");
            EXPECT_EQ(r.exitStatus, kExitError) << name << ": " << r.err;
            EXPECT_EQ(output(r)["alarm"].value("code", ""), "backup_error") << r.out;
            EXPECT_NE(r.err.find(std::string("SYSDISK/") + name + ": cannot read: " + c.says), std::string::npos)
                << r.err;
            EXPECT_EQ(r.err.find("every work offset is 0"), std::string::npos) << r.err;
            EXPECT_FALSE(fs::exists(dir_ / "machine"));
        }
        fs::remove_all(file);
        write(std::string("SYSDISK/") + name, bytes);
    }
}

// The .nc files are copied streaming, not read whole (a 270 MB program took 5 GB); the copy is the
// same bytes, and a second import into the folder compares them a chunk at a time.
TEST_F(CliImportTest, ProgramsAreCopiedAsTheyAreAndComparedOnASecondImport) {
    std::string big;
    for (int i = 0; i < 100000; ++i) {
        big += "G1 X" + std::to_string(i % 500) + " Y1 F900\n";
    }
    big += "M30\n";
    write("SYSDISK/big.nc", big);
    ProcessResult r = import("machine");
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(m350::testing::readFile(dir_ / "machine/big.nc"), big);
    ProcessResult again = import("machine");
    EXPECT_EQ(again.exitStatus, kExitOk) << again.err;
    write("machine/big.nc", big + "M30\n");
    ProcessResult changed = import("machine");
    EXPECT_EQ(changed.exitStatus, kExitError);
    EXPECT_NE(changed.err.find("big.nc differs"), std::string::npos) << changed.err;
}

TEST_F(CliImportTest, MissingArgumentsAreUsageErrors) {
    EXPECT_EQ(sim({"import", "SYSDISK"}).exitStatus, kExitUsage);
    EXPECT_EQ(sim({"import", "--into", "machine"}).exitStatus, kExitUsage);
    ProcessResult none = sim({"import", "nowhere", "--into", "machine"});
    EXPECT_EQ(none.exitStatus, kExitError);
    EXPECT_NE(none.err.find("nowhere: not a folder"), std::string::npos) << none.err;
}

} // namespace m350::clitest
