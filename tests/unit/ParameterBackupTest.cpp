// 参数备份 / 参数恢复 files and the Param page's layout and levels.
#include "core/files/AtomicFile.h"
#include "core/params/ParameterBackup.h"
#include "core/params/ParameterPages.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <variant>

namespace m350::config {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;
using testing::StartsWith;

const params::ParameterCatalogue& catalogue() {
    static const params::ParameterCatalogue loaded =
        std::get<params::ParameterCatalogue>(params::ParameterCatalogue::load(params::ParameterCatalogue::bundledPath()));
    return loaded;
}

fs::path backupFile(const std::string& name, const std::string& text) {
    fs::path file = fs::path(testing::TempDir()) / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

TEST(ParameterBackup, ABackupRestoresEveryParameterAsSaved) {
    params::ParameterTable table;
    table.set(61, 2500);
    table.set(546, 1); // an IO enable: not in the catalogue, still saved
    table.set(129, 10.25);
    fs::path file = backupFile("backup-ok.toml", params::formatParameterBackup(table, catalogue(), "m350 \"test\""));
    auto read = params::readParameterBackup(file, catalogue());
    ASSERT_TRUE(std::holds_alternative<params::ParameterRestore>(read)) << std::get<Message>(read).english();
    const params::ParameterRestore& restore = std::get<params::ParameterRestore>(read);
    ASSERT_EQ(restore.values.size(), 1000u);
    EXPECT_EQ(restore.values.at(61), 2500);
    EXPECT_EQ(restore.values.at(546), 1);
    EXPECT_EQ(restore.values.at(129), 10.25);
    EXPECT_EQ(restore.values.at(0), 0);
    EXPECT_FALSE(restore.outOfRange.empty()) << "param 1 (X pulses, 50 and up) is 0 here and is listed";
}

TEST(ParameterBackup, ABrokenFileIsRefusedWithItsLine) {
    fs::path file = backupFile("backup-broken.toml", "[backup]\nformat = 1\n[params]\n0 = 50\n1 = fifty\n");
    auto read = params::readParameterBackup(file, catalogue());
    ASSERT_TRUE(std::holds_alternative<Message>(read));
    EXPECT_THAT(std::get<Message>(read).english(), StartsWith(file.string() + ":5:"));
}

TEST(ParameterBackup, AFileThatIsNotABackupOrIsShortIsRefused) {
    auto other = params::readParameterBackup(backupFile("backup-other.toml", "[params]\n61 = 3000\n"), catalogue());
    ASSERT_TRUE(std::holds_alternative<Message>(other));
    EXPECT_THAT(std::get<Message>(other).english(), HasSubstr("not a parameter backup"));
    auto shortFile = params::readParameterBackup(backupFile("backup-short.toml", "[backup]\nformat = 1\n[params]\n61 = 3000\n"),
                                         catalogue());
    ASSERT_TRUE(std::holds_alternative<Message>(shortFile));
    EXPECT_THAT(std::get<Message>(shortFile).english(), HasSubstr("holds 1 parameters"));
    auto wrongKey = params::readParameterBackup(backupFile("backup-key.toml", "[backup]\nformat = 1\n[params]\n1000 = 3\n"),
                                        catalogue());
    ASSERT_TRUE(std::holds_alternative<Message>(wrongKey));
    EXPECT_THAT(std::get<Message>(wrongKey).english(), HasSubstr(":4:1: '1000' is not a parameter"));
}

TEST(ParameterPages, TabsHoldTheFirmwareGroupsAndEveryListedNumberIsFound) {
    params::ParameterPages pages(catalogue());
    std::size_t listed = 0;
    for (std::size_t c = 0; c < pages.categories().size(); ++c) {
        const auto& category = pages.categories()[c];
        for (std::size_t row = 0; row < category.numbers.size(); ++row) {
            auto at = pages.locate(category.numbers[row]);
            ASSERT_TRUE(at.has_value());
            EXPECT_EQ(at->category, c);
            EXPECT_EQ(at->row, row);
        }
        listed += category.numbers.size();
    }
    EXPECT_EQ(listed, 544u) << "584 catalogued, less the 40 CAM-teach rows of 1000 and up";
    EXPECT_FALSE(pages.locate(1027).has_value());
    EXPECT_EQ(pages.categories().front().group, 2) << "the user tab's Manual group first";
    EXPECT_EQ(pages.categories().back().group, params::ParameterPages::kUnlistedGroup);
}

TEST(ParameterPages, TheLevelFollowsTheTab) {
    EXPECT_EQ(params::ParameterPages::requiredLevel(2), params::UserLevel::Operator);  // 手动参数
    EXPECT_EQ(params::ParameterPages::requiredLevel(14), params::UserLevel::Operator); // 刀具参数
    EXPECT_EQ(params::ParameterPages::requiredLevel(1), params::UserLevel::Admin);     // 机床参数
    EXPECT_EQ(params::ParameterPages::requiredLevel(16), params::UserLevel::Admin);    // input port table
    EXPECT_EQ(params::ParameterPages::requiredLevel(0), params::UserLevel::Super);     // on no firmware page
    EXPECT_EQ(params::ParameterPages::tabOf(8), params::ParameterPages::Tab::User);
    EXPECT_EQ(params::ParameterPages::tabOf(15), params::ParameterPages::Tab::Factory);
}

} // namespace
} // namespace m350::config
