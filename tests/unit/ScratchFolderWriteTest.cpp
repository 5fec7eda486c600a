// A file of m350-hmi's throwaway machine copy (the scratch folder) is rewritten where it is, with
// no temp file and no rename; a link in it and every file outside it are still replaced whole.
#include "FileText.h"

#include "core/files/AtomicFile.h"
#include "core/files/ScratchFolder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include <sys/stat.h>

namespace m350::files {
namespace {

namespace fs = std::filesystem;
using m350::test::readText;
using m350::test::writeText;

ino_t inodeOf(const fs::path& file) {
    struct stat s {};
    EXPECT_EQ(::lstat(file.c_str(), &s), 0) << file;
    return s.st_ino;
}

class ScratchFolderWrite : public testing::Test {
protected:
    void SetUp() override {
        root_ = fs::path(testing::TempDir()) / ("scratch-folder-write-" + std::to_string(::getpid())); // parallel runs apart
        fs::remove_all(root_);
        fs::create_directories(root_ / "scratch");
        fs::create_directories(root_ / "kept");
        setScratchFolder(root_ / "scratch");
    }
    void TearDown() override {
        setScratchFolder({});
        fs::remove_all(root_);
    }
    fs::path root_;
};

TEST_F(ScratchFolderWrite, AFileInTheScratchFolderIsRewrittenWhereItIs) {
    const fs::path file = root_ / "scratch" / "mdi.nc";
    writeText(file, "G0 X100 Y100 Z100\n");
    ::chmod(file.c_str(), 0600);
    const ino_t before = inodeOf(file);
    ASSERT_EQ(writeFileAtomically(file, "G1 X1\n"), std::nullopt);
    EXPECT_EQ(readText(file), "G1 X1\n") << "shortened: the old tail is gone";
    EXPECT_EQ(inodeOf(file), before) << "no temp file renamed over it";
    struct stat s {};
    ::stat(file.c_str(), &s);
    EXPECT_EQ(s.st_mode & 07777, 0600u) << "its mode kept";
    ASSERT_EQ(writeFileAtomically(root_ / "scratch" / "new.nc", "M30\n"), std::nullopt);
    EXPECT_EQ(readText(root_ / "scratch" / "new.nc"), "M30\n");
    EXPECT_TRUE(staleTempFiles(file).empty());
}

TEST_F(ScratchFolderWrite, AFileOutsideItOrALinkInItIsStillReplacedWhole) {
    const fs::path kept = root_ / "kept" / "mdi.nc";
    writeText(kept, "G0 X0\n");
    const ino_t keptBefore = inodeOf(kept);
    ASSERT_EQ(writeFileAtomically(kept, "G1 X2\n"), std::nullopt);
    EXPECT_EQ(readText(kept), "G1 X2\n");
    EXPECT_NE(inodeOf(kept), keptBefore) << "a temp file renamed over it";

    // a link inside the scratch folder to a file outside it: replaced, the file it led to untouched
    const fs::path link = root_ / "scratch" / "linked.nc";
    fs::create_symlink(kept, link);
    ASSERT_EQ(writeFileAtomically(link, "G1 X3\n"), std::nullopt);
    EXPECT_EQ(readText(kept), "G1 X2\n");
    EXPECT_FALSE(fs::is_symlink(link));
    EXPECT_EQ(readText(link), "G1 X3\n");

    // a second name of a file outside: the same
    const fs::path hard = root_ / "scratch" / "hard.nc";
    fs::create_hard_link(kept, hard);
    ASSERT_EQ(writeFileAtomically(hard, "G1 X4\n"), std::nullopt);
    EXPECT_EQ(readText(kept), "G1 X2\n");
    EXPECT_EQ(readText(hard), "G1 X4\n");
}

// The file stays open between writes: each write still leaves exactly its content, and a file
// removed, replaced by another or given a second name in between is written as it now is.
TEST_F(ScratchFolderWrite, RepeatedWritesFollowTheNameNotAnOldHandle) {
    const fs::path file = root_ / "scratch" / "mdi.nc";
    for (const char* text : {"G91 G1 X0.05 F600\n", "G91 G1 X-0.05 F600\n", "M30\n", "", "G0 X1\nG0 Y2\n"}) {
        ASSERT_EQ(writeFileAtomically(file, text), std::nullopt);
        EXPECT_EQ(readText(file), text);
    }
    fs::remove(file);
    ASSERT_EQ(writeFileAtomically(file, "G1 X5\n"), std::nullopt);
    EXPECT_EQ(readText(file), "G1 X5\n") << "a removed file is made again";

    const fs::path other = root_ / "scratch" / "other.nc";
    writeText(other, "(other)\n");
    fs::rename(other, file); // someone replaced it: the old handle's file is gone from the name
    ASSERT_EQ(writeFileAtomically(file, "G1 X6\n"), std::nullopt);
    EXPECT_EQ(readText(file), "G1 X6\n");

    const fs::path second = root_ / "kept" / "second-name.nc";
    fs::create_hard_link(file, second);
    ASSERT_EQ(writeFileAtomically(file, "G1 X7\n"), std::nullopt);
    EXPECT_EQ(readText(file), "G1 X7\n");
    EXPECT_EQ(readText(second), "G1 X6\n") << "a file with two names is replaced, the other name keeps it";
    ASSERT_EQ(writeFileAtomically(file, "G1 X8\n"), std::nullopt);
    EXPECT_EQ(readText(file), "G1 X8\n");
    EXPECT_EQ(readText(second), "G1 X6\n");
}

} // namespace
} // namespace m350::files
