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
    Message error;
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
    Message error;
    std::size_t skipped = 0;
    ASSERT_TRUE(log.load(&error, &skipped)) << error;
    EXPECT_EQ(log.entries().size(), 2u);
    EXPECT_EQ(skipped, 1u);
}

TEST(SystemLog, StaysBoundedKeepingTheNewest) {
    TempLog temp;
    files::SystemLog log(temp.path(), 10);
    Message error;
    for (int i = 0; i < 45; ++i) {
        ASSERT_TRUE(log.append({"t", "mdi", std::to_string(i)}, &error)) << error;
    }
    files::SystemLog again(temp.path(), 10);
    ASSERT_TRUE(again.load(&error)) << error;
    EXPECT_LT(again.entries().size(), 20u);
    EXPECT_GE(again.entries().size(), 10u);
    EXPECT_EQ(again.entries().back().detail, "44");
}

// The log's own failures are said by message id in the language asked, with the OS's words (and
// a deeper layer's reason) nested as they come.
TEST(SystemLog, AFailureIsSaidInEitherLanguage) {
    TempLog temp;
    std::filesystem::create_directory(temp.path()); // the log's path is a folder
    files::SystemLog folder(temp.path());
    Message error;
    ASSERT_FALSE(folder.load(&error));
    EXPECT_EQ(error.id, "syslog_cannot_read");
    EXPECT_EQ(error.english().rfind(temp.path() + ": cannot read the system log: ", 0), 0u) << error;
    const std::string chinese = error.in(MessageLanguage::Chinese);
    EXPECT_EQ(chinese.rfind(temp.path() + "：无法读取系统日志：", 0), 0u) << chinese;
    EXPECT_EQ(chinese.find("cannot"), std::string::npos) << chinese;

    const std::string missing = (temp.dir / "gone" / "system-log.tsv").string(); // its folder is missing
    files::SystemLog nowhere(missing);
    ASSERT_TRUE(nowhere.load(&error)) << "a missing log is an empty one";
    ASSERT_FALSE(nowhere.append({"t", "mdi", "x"}, &error));
    EXPECT_EQ(error.id, "syslog_cannot_append");
    EXPECT_EQ(error.english(), missing + ": cannot append to the system log: No such file or directory");
    EXPECT_EQ(error.in(MessageLanguage::Chinese), missing + "：无法追加到系统日志（操作系统报告：No such file or directory）");

    const std::filesystem::path shortLived = temp.dir / "short";
    std::filesystem::create_directory(shortLived);
    files::SystemLog small((shortLived / "system-log.tsv").string(), 1);
    ASSERT_TRUE(small.append({"t", "mdi", "1"}, &error)) << error;
    std::filesystem::remove_all(shortLived);
    ASSERT_FALSE(small.append({"t", "mdi", "2"}, &error)) << "the second entry rewrites the log, whose folder is gone";
    EXPECT_EQ(error.id, "syslog_cannot_rewrite");
    EXPECT_NE(error.english().find(": cannot rewrite the system log: "), std::string::npos) << error;
    EXPECT_NE(error.in(MessageLanguage::Chinese).find("：无法重写系统日志："), std::string::npos) << error.in(MessageLanguage::Chinese);
}

} // namespace m350::test
