#include "core/files/SystemLog.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace m350::test {

namespace {

struct TempLog {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("m350-log-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempLog() { std::filesystem::create_directories(dir); }
    ~TempLog() { std::filesystem::remove_all(dir); }
    std::string path() const { return (dir / "system-log.tsv").string(); }
};

} // namespace

TEST(SystemLog, EntriesAppendedAreReadBack) {
    TempLog temp;
    std::string error;
    {
        files::SystemLog log(temp.path());
        ASSERT_TRUE(log.load(&error)) << error;
        EXPECT_TRUE(log.entries().empty());
        ASSERT_TRUE(log.append({"2026-11-23 10:00:00", "start_work", "part.nc"}, &error)) << error;
        ASSERT_TRUE(log.append({"2026-11-23 10:00:05", "alarm", "bad\tline\nhere"}, &error)) << error;
    }
    files::SystemLog again(temp.path());
    ASSERT_TRUE(again.load(&error)) << error;
    ASSERT_EQ(again.entries().size(), 2u);
    EXPECT_EQ(again.entries()[0].event, "start_work");
    EXPECT_EQ(again.entries()[0].detail, "part.nc");
    EXPECT_EQ(again.entries()[1].detail, "bad line here") << "tabs and line ends never split an entry";
}

TEST(SystemLog, ABrokenLineIsSkippedAndCounted) {
    TempLog temp;
    std::ofstream(temp.path()) << "2026-11-23 10:00:00\tpause\t\nno tabs at all\n2026-11-23 10:01:00\tresume\tx\n";
    files::SystemLog log(temp.path());
    std::string error;
    std::size_t skipped = 0;
    ASSERT_TRUE(log.load(&error, &skipped)) << error;
    EXPECT_EQ(log.entries().size(), 2u);
    EXPECT_EQ(skipped, 1u);
}

TEST(SystemLog, StaysBoundedKeepingTheNewest) {
    TempLog temp;
    files::SystemLog log(temp.path(), 10);
    std::string error;
    for (int i = 0; i < 45; ++i) {
        ASSERT_TRUE(log.append({"t", "mdi", std::to_string(i)}, &error)) << error;
    }
    files::SystemLog again(temp.path(), 10);
    ASSERT_TRUE(again.load(&error)) << error;
    EXPECT_LT(again.entries().size(), 20u);
    EXPECT_GE(again.entries().size(), 10u);
    EXPECT_EQ(again.entries().back().detail, "44");
}

} // namespace m350::test
