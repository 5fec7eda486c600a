// Issue 26: a kill -9 during a panel save left params.toml (930 = -89.5) and tool.tbl (T1 Z-88.5)
// disagreeing, and the older value won at the next start. The panel's save of parameters with the
// tool data is one change (files::writeTogether): a crash at any point leaves both old or both new.
#include "FileText.h"
#include "RunProgram.h"

#include "core/config/MachineFolder.h"
#include "core/controller/ToolTableSave.h"
#include "core/files/ChangeJournal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace m350;
using namespace m350::test;
namespace fs = std::filesystem;

constexpr const char* kParams = "[params]\n78 = 1\n800 = 1\n801 = 16\n930 = -88.5\n";
constexpr const char* kTable = "T1 P1 Z-88.5 ;roughing\nT2 P2 Z-40\n";

fs::path machineFolder(const std::string& name) {
    fs::path folder = fs::path(testing::TempDir()) / ("folder-change-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    writeText(folder / "machine.toml", "name = \"t\"\ndialect = \"m350\"\n");
    writeText(folder / "params.toml", kParams);
    writeText(folder / "tool.tbl", kTable);
    return folder;
}

config::MachineConfig load(const fs::path& folder) { return folderMachine(folder.string()); }

// The Param page sets 930 = -89.5 and saves, in a child process that `kill` ends with SIGKILL at
// the point it stands for, as a crash or a power cut would.
void killedParameterSave(const fs::path& folder, void (*kill)(files::AtomicWriteHooks&)) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        controller::Controller c(load(folder), {});
        c.setParameter(930, -89.5);
        files::AtomicWriteHooks hooks;
        kill(hooks);
        (void)controller::saveParameters(c, config::MachineFolder(folder), {{930, -89.5}}, hooks);
        _exit(0); // not reached: the hook killed us
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the save was not interrupted";
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

void expectNoLeftovers(const fs::path& folder) {
    EXPECT_FALSE(fs::exists(folder / "save.journal"));
    EXPECT_FALSE(fs::exists(folder / "tool.tbl.pending"));
    EXPECT_FALSE(fs::exists(folder / "params.toml.pending"));
}

TEST(FolderChange, ACrashBetweenTheToolTableAndParamsTomlLeavesTheNewStateInBoth) {
    const fs::path folder = machineFolder("between");
    killedParameterSave(folder, [](files::AtomicWriteHooks& hooks) { hooks.betweenFiles = [] { raise(SIGKILL); }; });
    ASSERT_TRUE(fs::exists(folder / "save.journal")) << "killed after the change happened, before it was tidied";

    const config::MachineConfig config = load(folder);
    for (const std::string& warning : config.warnings) {
        EXPECT_THAT(warning, testing::Not(testing::HasSubstr("the tool table is used"))) << "the files disagree";
    }
    controller::Controller c(config, {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -89.5) << "the new value, not the older one";
    EXPECT_DOUBLE_EQ(c.toolTableEdits().table().find(1)->offset(2), -89.5);
    EXPECT_THAT(readText(folder / "tool.tbl"), testing::HasSubstr("T1 P1 Z-89.5 ;roughing\n"));
    EXPECT_THAT(readText(folder / "params.toml"), testing::HasSubstr("930 = -89.5\n"));
    expectNoLeftovers(folder);
}

TEST(FolderChange, ACrashBeforeTheChangeLeavesTheOldStateInBoth) {
    const fs::path folder = machineFolder("before");
    killedParameterSave(folder, [](files::AtomicWriteHooks& hooks) { hooks.beforeRename = [] { raise(SIGKILL); }; });
    EXPECT_TRUE(fs::exists(folder / "tool.tbl.pending")) << "killed with the new content written aside";

    controller::Controller c(load(folder), {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -88.5);
    EXPECT_EQ(readText(folder / "tool.tbl"), kTable);
    EXPECT_EQ(readText(folder / "params.toml"), kParams);
    expectNoLeftovers(folder);
}

TEST(FolderChange, ASaveWithNoCrashWritesBothAndTheirLastGoodCopies) {
    const fs::path folder = machineFolder("whole");
    controller::Controller c(load(folder), {});
    ASSERT_TRUE(c.setParameter(930, -89.5));
    ASSERT_EQ(controller::saveParameters(c, config::MachineFolder(folder), {{930, -89.5}, {61, 2500}}), std::nullopt);
    EXPECT_FALSE(c.toolTableEdits().changed()) << "tool.tbl was saved with the parameters";
    EXPECT_THAT(readText(folder / "tool.tbl"), testing::HasSubstr("T1 P1 Z-89.5"));
    EXPECT_THAT(readText(folder / "params.toml"), testing::HasSubstr("930 = -89.5\n"));
    EXPECT_THAT(readText(folder / "params.toml"), testing::HasSubstr("61 = 2500\n"));
    EXPECT_EQ(readText(folder / "tool.tbl.last-good"), readText(folder / "tool.tbl"));
    EXPECT_EQ(readText(folder / "params.toml.last-good"), readText(folder / "params.toml"));
    expectNoLeftovers(folder);
}

TEST(FolderChange, AJournalThatIsNotWholeStopsTheLoadNamingIt) {
    const fs::path folder = machineFolder("garbled");
    writeText(folder / "save.journal", "m350 change\ntool.tbl 12 0123\n"); // no end line: made by hand
    auto loaded = config::loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<config::ConfigError>(loaded));
    EXPECT_EQ(std::get<config::ConfigError>(loaded).file, (folder / "save.journal").string());
    EXPECT_THAT(std::get<config::ConfigError>(loaded).message.english(), testing::HasSubstr("it has no end line"));
    EXPECT_EQ(readText(folder / "tool.tbl"), kTable) << "nothing is guessed";
}

} // namespace
