// params.toml written by the panel: values change in place, everything else stays, and a write
// interrupted at any point leaves the old file whole.
#include "FileText.h"

#include "core/files/AtomicFile.h"
#include "core/config/MachineConfig.h"
#include "core/config/MachineFolder.h"
#include "core/params/ParamsFileWriter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

#include <sys/wait.h>
#include <unistd.h>

namespace m350::config {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;
using testing::EndsWith;
using testing::StartsWith;

using m350::test::readText;
using m350::test::writeText;

fs::path freshFolder(const std::string& name) {
    fs::path folder = fs::path(testing::TempDir()) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    writeText(folder / "machine.toml", "name = \"t\"\n");
    return folder;
}

constexpr const char* kParams = "# Parameters of a test machine\n"
                                "[params]\n"
                                "61 = 3000  # default feed, mm/min\n"
                                "# spindle\n"
                                "81 =1.0# start delay\n"
                                "\"89\" = 0.5\n"
                                "\n"
                                "[other]\n"
                                "61 = 7\n";

TEST(ParamsFileWriter, ChangesValuesInPlaceAndKeepsCommentsAndOrder) {
    std::string out = params::setTomlNumbers(kParams, "params", {{61, 2500}, {81, 1.25}, {89, 2}});
    EXPECT_EQ(out, "# Parameters of a test machine\n"
                   "[params]\n"
                   "61 = 2500  # default feed, mm/min\n"
                   "# spindle\n"
                   "81 =1.25# start delay\n"
                   "\"89\" = 2\n"
                   "\n"
                   "[other]\n"
                   "61 = 7\n");
}

TEST(ParamsFileWriter, AddsAMissingKeyAfterTheTablesLastEntry) {
    std::string out = params::setTomlNumbers(kParams, "params", {{200, -0.001}, {130, 1}});
    EXPECT_THAT(out, HasSubstr("\"89\" = 0.5\n130 = 1\n200 = -0.001\n\n[other]\n"));
}

TEST(ParamsFileWriter, AddsTheTableWhenTheFileHasNone) {
    EXPECT_EQ(params::setTomlNumbers("# empty\n", "params", {{5, 1e-7}}), "# empty\n\n[params]\n5 = 1e-07\n");
    EXPECT_EQ(params::setTomlNumbers("", "params", {{5, 3}}), "[params]\n5 = 3\n");
}

TEST(ParamsFileWriter, TheMachineFolderLoadsWhatWasSaved) {
    fs::path folder = freshFolder("params-roundtrip");
    writeText(folder / "params.toml", kParams);
    ASSERT_EQ(config::MachineFolder(folder).saveParameters({{61, 1234.5}, {545, 22}}), std::nullopt);
    auto loaded = loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<MachineConfig>(loaded)) << std::get<ConfigError>(loaded).message;
    const MachineConfig& config = std::get<MachineConfig>(loaded);
    EXPECT_EQ(config.parameters.get(61), 1234.5);
    EXPECT_EQ(config.parameters.get(545), 22);
    EXPECT_EQ(config.parameters.get(89), 0.5);
    EXPECT_THAT(readText(folder / "params.toml"), StartsWith("# Parameters of a test machine\n[params]\n61 = 1234.5  #"));
    EXPECT_TRUE(files::staleTempFiles(folder / "params.toml").empty());
}

TEST(ParamsFileWriter, AHandBrokenFileIsStillReportedWithItsLine) {
    fs::path folder = freshFolder("params-broken");
    ASSERT_EQ(config::MachineFolder(folder).saveParameters({{61, 3000}, {62, 500}}), std::nullopt);
    writeText(folder / "params.toml", "[params]\n61 = 3000\n62 = = 500\n");
    auto loaded = loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<ConfigError>(loaded));
    const ConfigError& error = std::get<ConfigError>(loaded);
    EXPECT_THAT(error.file, HasSubstr("params.toml"));
    EXPECT_EQ(error.line, 3);
    EXPECT_THAT(error.where(), EndsWith("params.toml:3:6"));
}

// Runs `write` in a child process that the hook kills with SIGKILL, as a crash would.
void killedWrite(const fs::path& file, const std::string& content, bool duringChunks) {
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        files::AtomicWriteHooks hooks;
        if (duringChunks) hooks.afterChunk = [](std::size_t) { raise(SIGKILL); };
        else hooks.beforeRename = [] { raise(SIGKILL); };
        files::writeFileAtomically(file, content, hooks);
        _exit(0); // not reached: the hook killed us
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(ParamsFileWriter, AWriteKilledAtAnyPointLeavesTheOldFileWhole) {
    fs::path folder = freshFolder("params-killed");
    fs::path file = folder / "params.toml";
    writeText(file, kParams);
    std::string big = params::setTomlNumbers(kParams, "params", {{61, 1}}) + std::string(300 * 1024, '#') + "\n";
    killedWrite(file, big, true);
    EXPECT_EQ(readText(file), kParams) << "killed while the temp file was half written";
    const std::vector<fs::path> halfWritten = files::staleTempFiles(file);
    ASSERT_EQ(halfWritten.size(), 1u) << "the killed writer's own temp file";
    EXPECT_LT(fs::file_size(halfWritten[0]), big.size()) << "the half file is the temp, not the target";
    killedWrite(file, big, false);
    EXPECT_EQ(readText(file), kParams) << "killed after the temp was synced, before the rename";
    EXPECT_EQ(files::staleTempFiles(file).size(), 2u) << "each writer had a temp file of its own";
    ASSERT_EQ(files::writeFileAtomically(file, big), std::nullopt) << "the next write removes the stale temps";
    EXPECT_EQ(readText(file), big);
    EXPECT_TRUE(files::staleTempFiles(file).empty());
}

TEST(ParamsFileWriter, AFailedWriteSaysWhichFile) {
    fs::path missing = fs::path(testing::TempDir()) / "no-such-folder" / "params.toml";
    auto error = files::writeFileAtomically(missing, "x");
    ASSERT_TRUE(error.has_value());
    EXPECT_THAT(error->english(), HasSubstr("no-such-folder"));
}

} // namespace
} // namespace m350::config
