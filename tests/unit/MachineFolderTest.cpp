// The machine folder's store (config::MachineFolder): where each file is, how it is written, and
// which paths are files of the folder.
#include "FileText.h"

#include "core/config/MachineFolder.h"
#include "core/files/LastGoodCopy.h"
#include "core/tools/ToolLifeFile.h"
#include "core/tools/ToolTableFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

#include <sys/resource.h>

namespace m350 {
namespace {

namespace fs = std::filesystem;
using config::FolderFile;
using config::FolderWrite;
using config::MachineFolder;
using test::readText;
using test::writeText;
using testing::HasSubstr;

fs::path freshFolder(const std::string& name) {
    fs::path folder = fs::temp_directory_path() / ("m350-machine-folder-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// Files larger than `bytes` cannot be written while it lives (RLIMIT_FSIZE; SIGXFSZ ignored, so a
// write fails with EFBIG): a disk that fills up mid-write, also for root.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

TEST(MachineFolder, EachFileItWritesLandsWholeWithItsLastGoodCopyWhereDue) {
    const fs::path folder = freshFolder("write");
    const MachineFolder store(folder);
    int written = 0;
    for (const config::FolderFileInfo& info : MachineFolder::files()) {
        EXPECT_EQ(MachineFolder::fileName(info.file), info.name);
        EXPECT_EQ(store.pathOf(info.file), folder / info.name);
        if (info.how == FolderWrite::Never || info.how == FolderWrite::Appended) {
            continue;
        }
        const std::string content = "content of " + std::string(info.name) + "\n";
        ASSERT_EQ(store.write(info.file, content), std::nullopt) << info.name;
        EXPECT_EQ(readText(folder / info.name), content);
        EXPECT_EQ(fs::exists(files::lastGoodPath(folder / info.name)), info.how == FolderWrite::KeepingLastGood)
            << info.name;
        if (info.how == FolderWrite::KeepingLastGood) {
            EXPECT_EQ(readText(files::lastGoodPath(folder / info.name)), content);
        }
        ++written;
    }
    EXPECT_EQ(written, 10) << "params.toml tool.tbl toollife.txt passwords.toml mdiblock mdi.nc breakpoint "
                              "dprnt.txt params-backup.toml PROCES_MSG.txt";
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        EXPECT_NE(entry.path().filename().string().front(), '.') << "no temp file is left: " << entry.path();
    }
}

TEST(MachineFolder, TheFilesItOnlyReadsOrThatAreAppendedAreNotWrittenWhole) {
    const fs::path folder = freshFolder("inputs");
    writeText(folder / "machine.toml", "name = \"m\"\n");
    const MachineFolder store(folder);
    EXPECT_THAT(store.write(FolderFile::Machine, "x").value_or(Message{}).english(), HasSubstr("machine.toml: not written whole"));
    EXPECT_THAT(store.write(FolderFile::SystemLog, "x").value_or(Message{}).english(), HasSubstr("system-log.tsv: not written whole"));
    EXPECT_EQ(readText(folder / "machine.toml"), "name = \"m\"\n");
    EXPECT_FALSE(fs::exists(folder / "system-log.tsv"));
}

TEST(MachineFolder, AMachineWithoutAFolderKeepsNothing) {
    const MachineFolder store{fs::path()};
    EXPECT_EQ(store.write(FolderFile::MdiBlock, "x"), "this machine has no folder to keep mdiblock in");
    EXPECT_EQ(store.saveToolTable(tools::ToolTable{}, {}), "this machine has no folder to keep its tool table in");
    EXPECT_FALSE(store.isFolderFile("params.toml"));
}

TEST(MachineFolder, AFailedWriteLeavesTheOldFileAndSaysWhy) {
    const fs::path folder = freshFolder("failed");
    const MachineFolder store(folder);
    ASSERT_EQ(store.write(FolderFile::ToolTable, "T1 P1 Z-50\n"), std::nullopt);
    ASSERT_EQ(store.write(FolderFile::Passwords, "old\n"), std::nullopt);
    std::optional<Message> toolTable, passwords;
    {
        FileSizeLimit limit(64);
        toolTable = store.write(FolderFile::ToolTable, std::string(4096, ';') + "\n");
        passwords = store.write(FolderFile::Passwords, std::string(4096, '#') + "\n");
    }
    ASSERT_TRUE(toolTable);
    EXPECT_THAT(toolTable->english(), HasSubstr("tool.tbl"));
    ASSERT_TRUE(passwords);
    EXPECT_THAT(passwords->english(), HasSubstr("passwords.toml"));
    EXPECT_EQ(readText(folder / "tool.tbl"), "T1 P1 Z-50\n");
    EXPECT_EQ(readText(files::lastGoodPath(folder / "tool.tbl")), "T1 P1 Z-50\n");
    EXPECT_EQ(readText(folder / "passwords.toml"), "old\n");
}

TEST(MachineFolder, ParametersAreEditedInPlaceKeepingEveryOtherByte) {
    const fs::path folder = freshFolder("params");
    writeText(folder / "params.toml", "# the router\n[params]\n61 = 1000 # feed\n");
    const MachineFolder store(folder);
    ASSERT_EQ(store.saveParameters({{61, 3000}, {62, 500}}), std::nullopt);
    const std::string expected = "# the router\n[params]\n61 = 3000 # feed\n62 = 500\n";
    EXPECT_EQ(readText(folder / "params.toml"), expected);
    EXPECT_EQ(readText(files::lastGoodPath(folder / "params.toml")), expected);
    ASSERT_EQ(store.saveParameters({{63, 1}}, false), std::nullopt);
    EXPECT_EQ(readText(folder / "params.toml"), expected) << "without addMissing only listed values change";
}

// A value goes into params.toml at its parameter's resolution: a measured tool length without the
// double's last-digit noise, a select or an int whole, a real to four decimals (135's factory 5.7195).
TEST(MachineFolder, ParametersAreWrittenAtTheirResolution) {
    const fs::path folder = freshFolder("params-resolution");
    writeText(folder / "params.toml", "[params]\n930 = -50\n");
    const MachineFolder store(folder);
    ASSERT_EQ(store.saveParameters({{930, -48.120000000000005}, {135, 5.71950000001}, {7, 0.9999999}, {11, 7000.4},
                                    {61, -0.00001}}),
              std::nullopt);
    EXPECT_EQ(readText(folder / "params.toml"), "[params]\n930 = -48.12\n7 = 1\n11 = 7000\n61 = 0\n135 = 5.7195\n");
}

TEST(MachineFolder, TheToolTableGoesIntoToolTblAndItsZIntoTheParametersParamsTomlLists) {
    const fs::path folder = freshFolder("tools");
    writeText(folder / "params.toml", "[params]\n930 = -50\n");
    const MachineFolder store(folder);
    const tools::ToolTable table = tools::parseToolTable("; tools\nT1 P1 Z-80\nT2 P2 Z-41.5\n", "tool.tbl").table;
    ASSERT_EQ(store.saveToolTable(table, {{930, -80}, {931, -41.5}}), std::nullopt);
    EXPECT_EQ(readText(folder / "tool.tbl"), "; tools\nT1 P1 Z-80\nT2 P2 Z-41.5\n");
    EXPECT_EQ(readText(files::lastGoodPath(folder / "tool.tbl")), readText(folder / "tool.tbl"));
    EXPECT_EQ(readText(folder / "params.toml"), "[params]\n930 = -80\n") << "nothing is added: tool.tbl is read";
}

TEST(MachineFolder, ToolLifeDataGoesIntoToollifeTxtWithItsLastGoodCopy) {
    const fs::path folder = freshFolder("life");
    tools::LifeData life;
    life.putGroup({1, 100, tools::LifeKind::Count, {{1, 0, 0, 5}}});
    ASSERT_EQ(MachineFolder(folder).saveToolLife(life), std::nullopt);
    EXPECT_EQ(readText(folder / "toollife.txt"), tools::formatToolLife(life));
    EXPECT_EQ(readText(files::lastGoodPath(folder / "toollife.txt")), tools::formatToolLife(life));
}

TEST(MachineFolder, EachFileOfTheFolderIsOneAndAPathOutsideIsNot) {
    const fs::path folder = freshFolder("query");
    const MachineFolder store(folder);
    for (const config::FolderFileInfo& info : MachineFolder::files()) {
        EXPECT_TRUE(store.isFolderFile(folder / info.name)) << info.name;
        EXPECT_TRUE(store.isFolderFile(files::lastGoodPath(folder / info.name))) << info.name;
        EXPECT_FALSE(store.isFolderFile(folder.parent_path() / info.name)) << info.name;
        EXPECT_FALSE(store.isFolderFile(folder / "sub" / info.name)) << info.name;
    }
    EXPECT_TRUE(store.isFolderFile(folder / "fndzero.nc")) << "a hook program";
    EXPECT_TRUE(store.isFolderFile(folder / "FNDZERO.NC")) << "in another case, as hookPath finds it";
    EXPECT_FALSE(store.isFolderFile(folder / "fndzero")) << "not a hook file name";
    EXPECT_FALSE(store.isFolderFile(folder / "part.nc")) << "a program: not the folder's own";
    EXPECT_FALSE(store.isFolderFile(folder / "tool-export.tbl"));
    EXPECT_FALSE(store.isFolderFile(folder));
    EXPECT_TRUE(store.isFolderFile(folder / "sub" / ".." / "params.toml"));
    EXPECT_EQ(store.refuseFolderFile(folder / "tool.tbl"),
              (folder / "tool.tbl").string() + " is a file of the machine folder " + folder.string() +
                  ": refused, nothing was written");
    EXPECT_EQ(store.refuseFolderFile(folder / "part.nc"), std::nullopt);
}

TEST(MachineFolder, ASymlinkIntoTheFolderIsAFileOfIt) {
    const fs::path folder = freshFolder("linked");
    const fs::path outside = freshFolder("linked-outside");
    writeText(folder / "params.toml", "[params]\n");
    const MachineFolder store(folder);
    fs::create_symlink(folder / "params.toml", outside / "settings.toml");
    fs::create_symlink(folder / "breakpoint", outside / "dangling"); // breakpoint does not exist yet
    fs::create_symlink(folder, outside / "folder-link");
    fs::create_symlink("../m350-machine-folder-linked/tool.tbl", outside / "relative");
    EXPECT_TRUE(store.isFolderFile(outside / "settings.toml"));
    EXPECT_TRUE(store.isFolderFile(outside / "dangling"));
    EXPECT_TRUE(store.isFolderFile(outside / "folder-link" / "mdiblock"));
    EXPECT_TRUE(store.isFolderFile(outside / "relative"));
    EXPECT_TRUE(MachineFolder(outside / "folder-link").isFolderFile(folder / "tool.tbl"))
        << "the store of a folder reached through a symlink";
    writeText(outside / "plain.txt", "x");
    fs::create_symlink(outside / "plain.txt", folder / "plain-link.txt");
    EXPECT_FALSE(store.isFolderFile(folder / "plain-link.txt")) << "resolves outside, and is no folder file";
}

TEST(MachineFolder, AToolTableExportIsRefusedOverAFolderFile) {
    const fs::path folder = freshFolder("export");
    writeText(folder / "tool.tbl", "T1 P1 Z-50\n");
    const MachineFolder store(folder);
    const tools::ToolTable table = tools::parseToolTable("T7 P7 Z-12\n", "tool.tbl").table;
    EXPECT_THAT(store.exportToolTable(folder / "tool.tbl", table).value_or(Message{}).english(), HasSubstr("refused, nothing was written"));
    EXPECT_EQ(readText(folder / "tool.tbl"), "T1 P1 Z-50\n");
    ASSERT_EQ(store.exportToolTable(folder / "tool-export.tbl", table), std::nullopt);
    EXPECT_EQ(readText(folder / "tool-export.tbl"), "T7 P7 Z-12\n");
}

} // namespace
} // namespace m350
