// Importing a controller backup (core/backup/BackupImport): the machine folder loads with the
// backup's exact parameters and offsets, keeps its files' bytes, is the same twice, and a damaged
// backup or a folder holding something else is refused with nothing written.
#include "core/backup/BackupImport.h"
#include "core/config/MachineConfig.h"
#include "tests/support/ControllerBackupWriter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace m350::config {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using m350::testing::ControllerBackupWriter;
using m350::testing::readFile;

class BackupImportTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(::testing::TempDir()) / ("backup-import-" + std::to_string(::getpid()) + "-" +
                                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        backup_ = ControllerBackupWriter::smallRouter();
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::variant<backup::BackupImport, backup::ImportError> import(const std::string& into = "machine") {
        backup_.writeTo(dir_ / "SYSDISK");
        return backup::importControllerBackup(dir_ / "SYSDISK", dir_ / into, MessageLanguage::English);
    }
    backup::BackupImport imported(const std::string& into = "machine") {
        auto result = import(into);
        if (auto* error = std::get_if<backup::ImportError>(&result)) {
            ADD_FAILURE() << error->file << ": " << error->message;
            return {};
        }
        return std::get<backup::BackupImport>(result);
    }
    backup::ImportError refused(const std::string& into = "machine") {
        auto result = import(into);
        EXPECT_TRUE(std::holds_alternative<backup::ImportError>(result));
        return std::holds_alternative<backup::ImportError>(result) ? std::get<backup::ImportError>(result) : backup::ImportError{};
    }
    MachineConfig load(const std::string& folder = "machine") {
        auto loaded = loadMachineFolder((dir_ / folder).string());
        if (auto* error = std::get_if<ConfigError>(&loaded)) {
            ADD_FAILURE() << error->file << ": " << error->message;
            return {};
        }
        return std::get<MachineConfig>(loaded);
    }
    // Everything under the test's folder except the backup: what an import left behind.
    std::vector<std::string> leftBehind() {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            if (entry.path().filename() != "SYSDISK") {
                names.push_back(entry.path().filename().string());
            }
        }
        return names;
    }

    fs::path dir_;
    ControllerBackupWriter backup_;
};

TEST_F(BackupImportTest, EveryParameterAndOffsetLoadsExactlyAsTheBinaryFilesHoldThem) {
    backup_.setting[140] = 0.1 + 0.2; // a value with no short decimal form
    backup_.setting[136] = -1.0 / 3.0;
    backup_.coordinate[8] = 1e-7;
    imported();
    MachineConfig machine = load();
    for (int n = 0; n < params::ParameterTable::kCount; ++n) {
        EXPECT_EQ(machine.parameters.get(n), backup_.setting[static_cast<std::size_t>(n)]) << "parameter " << n;
    }
    for (std::size_t i = 0; i < 45; ++i) {
        EXPECT_EQ(machine.offsets[i / 5][i % 5], backup_.coordinate[i]) << "#" << 800 + i;
    }
    EXPECT_EQ(machine.dialect->id, gcode::DialectId::M350);
    ASSERT_EQ(machine.libraries.size(), 2u);
    EXPECT_EQ(fs::path(machine.libraries[0].path).filename(), "slib-g.nc");
    EXPECT_EQ(machine.libraries[0].role, gcode::FileRole::GLibrary);
    EXPECT_EQ(machine.libraries[1].role, gcode::FileRole::MLibrary);
}

TEST_F(BackupImportTest, SlibuserNcLoadsBesideSlibGOnceAndTheHookFilesAreListed) {
    backup_.files["slibuser.nc"] = "O9199(G199)\nG90 G01 X#0 Y#1 F1000\nM99\n";
    backup::BackupImport result = imported();
    EXPECT_EQ(result.libraries, (std::vector<std::string>{"slib-g.nc", "slib-m.nc", "slibuser.nc"}));
    MachineConfig machine = load();
    ASSERT_EQ(machine.libraries.size(), 3u);
    EXPECT_EQ(fs::path(machine.libraries[2].path).filename(), "slibuser.nc");
    EXPECT_EQ(machine.libraries[2].role, gcode::FileRole::GLibrary);
    ASSERT_EQ(result.hooks.size(), 2u); // T.nc and pause.nc; slibuser.nc is a library, cam/cam1.nc no hook
    EXPECT_THAT(backup::formatImportReport(result, MessageLanguage::English), HasSubstr("\n  pause.nc: "));
}

TEST_F(BackupImportTest, NamesInAnotherCaseAsAFatStickLeavesThemAreFound) {
    backup_.files["SLIB-G.NC"] = backup_.files["slib-g.nc"];
    backup_.files.erase("slib-g.nc");
    backup_.writeTo(dir_ / "SYSDISK");
    fs::rename(dir_ / "SYSDISK/setting", dir_ / "SYSDISK/SETTING");
    fs::rename(dir_ / "SYSDISK/coordinate", dir_ / "SYSDISK/COORDINATE");
    auto result = backup::importControllerBackup(dir_ / "SYSDISK", dir_ / "machine", MessageLanguage::English);
    ASSERT_TRUE(std::holds_alternative<backup::BackupImport>(result)) << std::get<backup::ImportError>(result).message;
    const backup::BackupImport& r = std::get<backup::BackupImport>(result);
    EXPECT_EQ(r.libraries[0], "SLIB-G.NC");
    EXPECT_TRUE(r.offsets);
    EXPECT_TRUE(std::none_of(r.skipped.begin(), r.skipped.end(),
                             [](const backup::SkippedFile& f) { return f.name == "SETTING" || f.name == "COORDINATE"; }));
    MachineConfig machine = load();
    EXPECT_EQ(machine.parameters.get(129), backup_.setting[129]);
    EXPECT_EQ(machine.offsets[1][0], backup_.coordinate[5]);
    EXPECT_EQ(fs::path(machine.libraries[0].path).filename(), "SLIB-G.NC");
}

TEST_F(BackupImportTest, ParamsTomlNamesEachParameterAndMarksWhatDiffersFromTheFactory) {
    backup::BackupImport result = imported();
    const std::string params = readFile(dir_ / "machine/params.toml");
    EXPECT_THAT(params, HasSubstr("\n129 = 7.25  # 浮动对刀仪厚度 Floating tool set thickness; factory: 10\n"));
    EXPECT_THAT(params, HasSubstr("\n546 = 1  # enable of 545 X轴零点信号"));
    EXPECT_THAT(params, HasSubstr("\n547 = 1  # active level of 545 X轴零点信号"));
    EXPECT_THAT(params, HasSubstr("\n0 = 50  # 电机起跳速度 Motor starting speed\n")); // as the factory's: no mark
    EXPECT_TRUE(result.factoryCompared);
    EXPECT_TRUE(std::find(result.changedParameters.begin(), result.changedParameters.end(), 129) !=
                result.changedParameters.end());
    EXPECT_TRUE(std::find(result.changedParameters.begin(), result.changedParameters.end(), 0) ==
                result.changedParameters.end());
}

TEST_F(BackupImportTest, WithoutDefaultSettingNothingIsComparedAndTheReportSaysSo) {
    backup_.withDefaults = false;
    backup::BackupImport result = imported();
    EXPECT_FALSE(result.factoryCompared);
    EXPECT_TRUE(result.changedParameters.empty());
    EXPECT_THAT(readFile(dir_ / "machine/params.toml"), ::testing::Not(HasSubstr("factory:")));
    EXPECT_THAT(backup::formatImportReport(result, MessageLanguage::English), HasSubstr("no default_setting"));
}

TEST_F(BackupImportTest, TheMdiLinesAndTheNcFilesKeepTheirBytes) {
    backup::BackupImport result = imported();
    EXPECT_EQ(readFile(dir_ / "machine/mdiblock"), m350::testing::mdiBlock(backup_.mdiLines));
    ASSERT_EQ(result.mdiLines.size(), 6u);
    EXPECT_EQ(result.mdiLines[0], "G90 G0 X20 Y10");
    EXPECT_EQ(result.mdiLines[3], "(MDI 测试)"); // decoded from GBK for the report
    for (const auto& [name, bytes] : backup_.files) {
        if (fs::path(name).extension() == ".nc") {
            EXPECT_EQ(readFile(dir_ / "machine" / name), bytes) << name;
        } else {
            EXPECT_FALSE(fs::exists(dir_ / "machine" / name)) << name << " is not the simulator's";
        }
    }
}

TEST_F(BackupImportTest, AnMdiBlockOfTheWrongSizeIsReadAsFarAsItGoesAndSaid) {
    backup_.writeTo(dir_ / "SYSDISK");
    std::ofstream(dir_ / "SYSDISK/mdiblock", std::ios::binary) << std::string("G0 X1\0\0\0", 8) + "M3";
    auto result = backup::importControllerBackup(dir_ / "SYSDISK", dir_ / "machine", MessageLanguage::English);
    ASSERT_TRUE(std::holds_alternative<backup::BackupImport>(result));
    const backup::BackupImport& r = std::get<backup::BackupImport>(result);
    EXPECT_EQ(r.mdiLines[0], "G0 X1");
    EXPECT_EQ(r.mdiLines[1], "");
    EXPECT_EQ(readFile(dir_ / "machine/mdiblock").size(), 720u);
    EXPECT_THAT(backup::formatImportReport(r, MessageLanguage::English), HasSubstr("mdiblock holds 10 bytes, not 720"));
}

TEST_F(BackupImportTest, TwoImportsOfOneBackupAreTheSameBytesAndTheSecondIntoTheFirstWritesNothing) {
    backup::BackupImport first = imported("a");
    backup::BackupImport second = imported("b");
    ASSERT_EQ(first.written, second.written);
    for (const std::string& name : first.written) {
        EXPECT_EQ(readFile(dir_ / "a" / name), readFile(dir_ / "b" / name)) << name;
    }
    const auto before = fs::last_write_time(dir_ / "a/params.toml");
    backup::BackupImport again = imported("a");
    EXPECT_TRUE(again.unchanged);
    EXPECT_EQ(fs::last_write_time(dir_ / "a/params.toml"), before);
}

TEST_F(BackupImportTest, AnImportChangedSinceIsNotOverwritten) {
    imported();
    std::ofstream(dir_ / "machine/params.toml", std::ios::app) << "# my note\n";
    const std::string mine = readFile(dir_ / "machine/params.toml");
    backup::ImportError error = refused();
    EXPECT_EQ(error.code, "machine_folder_not_empty");
    EXPECT_THAT(error.message.english(), HasSubstr("params.toml differs"));
    EXPECT_EQ(readFile(dir_ / "machine/params.toml"), mine);
}

TEST_F(BackupImportTest, AnEmptyFolderIsFilledAndAFolderInsideTheBackupRefused) {
    fs::create_directories(dir_ / "empty");
    imported("empty");
    EXPECT_TRUE(fs::exists(dir_ / "empty/machine.toml"));
    backup::ImportError inside = refused("SYSDISK/machine");
    EXPECT_THAT(inside.message.english(), HasSubstr("inside the backup"));
    EXPECT_FALSE(fs::exists(dir_ / "SYSDISK/machine"));
}

TEST_F(BackupImportTest, ADamagedSettingIsRefusedNamingTheFileOffsetAndParameterAndNothingIsWritten) {
    struct Case {
        int parameter;
        double value;
        const char* says;
    };
    const double inf = std::numeric_limits<double>::infinity();
    for (const Case& c : {Case{129, std::nan(""), "the value is nan"}, Case{806, -inf, "the value is -infinity"},
                          Case{61, 3e200, "no parameter or offset a controller stores"},
                          Case{62, 4.9e-324, "no parameter or offset a controller stores"}}) {
        backup_ = ControllerBackupWriter::smallRouter();
        backup_.setting[static_cast<std::size_t>(c.parameter)] = c.value;
        backup::ImportError error = refused();
        EXPECT_EQ(error.code, "backup_error");
        EXPECT_EQ(error.file, (dir_ / "SYSDISK/setting").string());
        EXPECT_THAT(error.message.english(), HasSubstr("offset " + std::to_string(c.parameter * 8) + ", parameter " +
                                             std::to_string(c.parameter) + " ("));
        EXPECT_THAT(error.message.english(), HasSubstr(c.says));
        EXPECT_THAT(error.message.english(), HasSubstr("nothing imported"));
        EXPECT_TRUE(leftBehind().empty());
    }
}

TEST_F(BackupImportTest, WrongSizesAndAMissingSettingAreRefused) {
    backup_.writeTo(dir_ / "SYSDISK");
    std::ofstream(dir_ / "SYSDISK/coordinate", std::ios::binary | std::ios::app) << "x";
    auto longer = backup::importControllerBackup(dir_ / "SYSDISK", dir_ / "machine", MessageLanguage::English);
    ASSERT_TRUE(std::holds_alternative<backup::ImportError>(longer));
    EXPECT_THAT(std::get<backup::ImportError>(longer).message.english(),
                HasSubstr("holds 361 bytes; a coordinate file holds 45 little-endian float64 (360 bytes)"));
    fs::remove(dir_ / "SYSDISK/setting");
    auto missing = backup::importControllerBackup(dir_ / "SYSDISK", dir_ / "machine", MessageLanguage::English);
    ASSERT_TRUE(std::holds_alternative<backup::ImportError>(missing));
    EXPECT_THAT(std::get<backup::ImportError>(missing).message.english(), HasSubstr("not found"));
    EXPECT_TRUE(leftBehind().empty());
}

TEST_F(BackupImportTest, ABigEndianCopyIsRefusedAsDamaged) {
    backup_.writeTo(dir_ / "SYSDISK");
    std::string setting = readFile(dir_ / "SYSDISK/setting");
    for (std::size_t i = 0; i < setting.size(); i += 8) {
        std::reverse(setting.begin() + static_cast<std::ptrdiff_t>(i), setting.begin() + static_cast<std::ptrdiff_t>(i + 8));
    }
    std::ofstream(dir_ / "SYSDISK/setting", std::ios::binary) << setting;
    auto result = backup::importControllerBackup(dir_ / "SYSDISK", dir_ / "machine", MessageLanguage::English);
    ASSERT_TRUE(std::holds_alternative<backup::ImportError>(result));
    EXPECT_THAT(std::get<backup::ImportError>(result).message.english(), HasSubstr("the file is damaged"));
}

TEST_F(BackupImportTest, TheReportSaysWhatToReviewAndWhatCannotBeModelled) {
    backup::BackupImport result = imported();
    const std::string report = readFile(dir_ / "machine" / backup::kImportReportFile);
    EXPECT_EQ(report, backup::formatImportReport(result, MessageLanguage::English));
    EXPECT_THAT(report, HasSubstr("magazine type 4 (servo disc, 圆盘刀库) is not modelled"));
    for (const char* key : {"homing.switch_distance", "tool_setter.top", "floating_setter.top", "tools.length",
                            "io_links"}) {
        EXPECT_THAT(report, HasSubstr(std::string(key) + " = ")) << key;
    }
    EXPECT_THAT(report, HasSubstr("sys.log: log"));
    EXPECT_THAT(report, HasSubstr("drivers/m350io.ko: kernel module"));
    EXPECT_THAT(report, ::testing::Not(HasSubstr(dir_.string()))); // no paths: the same backup, the same text
}

TEST_F(BackupImportTest, SyntaxTheSimulatorDoesNotAcceptIsListedPerFile) {
    backup_.files["key-1.nc"] = "G0 X[1+\n";
    backup::BackupImport result = imported();
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].file, "key-1.nc");
    EXPECT_EQ(result.diagnostics[0].line, 1u);
    EXPECT_THAT(backup::formatImportReport(result, MessageLanguage::English), HasSubstr("key-1.nc:1:"));
}

TEST_F(BackupImportTest, ToolLengthsMakeTheStoredZOffsetsTrueOnTheSimulatedSetter) {
    imported();
    MachineConfig machine = load();
    // a tool trips the setter with its nose at top + length: where the controller stored it
    ASSERT_GE(machine.toolLengths.size(), 2u);
    EXPECT_DOUBLE_EQ(machine.setterTop + machine.toolLengths[0], backup_.setting[930]);
    EXPECT_DOUBLE_EQ(machine.setterTop + machine.toolLengths[1], backup_.setting[931]);
    EXPECT_EQ(machine.toolLengths.size(), 6u); // the capacity, param 801
    ASSERT_TRUE(machine.floatingSetterTop);
}

} // namespace
} // namespace m350::config
