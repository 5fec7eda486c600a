// The M350's tool Z offsets (params 930-945, virtual tools 973-992) and the tool table's Z column
// are one store; the table lives in the machine folder's tool.tbl, survives a reload with its
// comments, and a write killed at any point leaves the old file whole.
#include "FileText.h"
#include "RunProgram.h"

#include "core/config/MachineFolder.h"
#include "core/controller/ToolTableSave.h"
#include "core/files/AtomicFile.h"
#include "core/tools/ToolTableFile.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace m350;
using namespace m350::test;
using testing::HasSubstr;
namespace fs = std::filesystem;

constexpr const char* kToolTable = "; the router's tools\n"
                                   "T1 P1 Z-50 ;roughing {rpm=18000 teeth=3 type=flat}\n"
                                   "T2 P2 Z-40\n"
                                   "T20 P20 Z-30 ;virtual: changed by hand\n"
                                   "T50 P50 Z1 ;kept, though the M350 has no offset for it\n";

// An M350 folder with 16 pockets, tool 1 in the spindle, G54 active.
fs::path machineFolder(const std::string& name, const std::string& params, const char* table) {
    fs::path folder = fs::path(testing::TempDir()) / ("tooldata-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    writeText(folder / "machine.toml", "name = \"t\"\ndialect = \"m350\"\n");
    writeText(folder / "params.toml", "[params]\n78 = 1\n800 = 1\n801 = 16\n" + params);
    if (table) {
        writeText(folder / "tool.tbl", table);
    }
    return folder;
}

config::MachineConfig load(const fs::path& folder) { return folderMachine(folder.string()); }

TEST(ToolData, TheParametersAndTheTablesZAreOneStoreWhoeverWrites) {
    controller::Controller c(load(machineFolder("one-store", "", kToolTable)), {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -50.0) << "tool.tbl sets T1's parameter";
    EXPECT_DOUBLE_EQ(c.parameter(976), -30.0) << "T20 is virtual tool 4 (16 + 4): parameter 973 + 3";
    ASSERT_TRUE(c.loadMdi({"#1431 = -41.5", "#1432 = -33"})); // as O502 stores a set tool
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    tools::ToolTable table = c.toolTableEdits().table();
    EXPECT_DOUBLE_EQ(table.find(2)->offset(tools::kZ), -41.5) << "a macro's #1431 is the table's T2 Z";
    ASSERT_NE(table.find(3), nullptr) << "T3 has a parameter: it joins the table once set";
    EXPECT_EQ(table.find(3)->pocket, 3);
    tools::ToolEntry t1 = *table.find(1);
    t1.offsets[tools::kZ] = -52.25;
    ASSERT_TRUE(c.toolTableEdits().putTool(t1));
    EXPECT_DOUBLE_EQ(c.variable(1430).number, -52.25) << "an edit of the table is #1430";
    ASSERT_TRUE(c.setParameter(945, -10.0)); // the Param page
    EXPECT_DOUBLE_EQ(c.toolTableEdits().table().find(16)->offset(tools::kZ), -10.0);
    ASSERT_TRUE(c.toolTableEdits().removeTool(2));
    EXPECT_DOUBLE_EQ(c.parameter(931), 0.0) << "a tool taken out of the table has no Z left";
    EXPECT_DOUBLE_EQ(c.toolTableEdits().table().find(50)->offset(tools::kZ), 1.0) << "a tool beyond the M350's keeps its own Z";
}

TEST(ToolData, WithoutAToolTableTheM350StartsFromItsParameters) {
    controller::Controller c(load(machineFolder("seeded", "930 = -53.677\n931 = -41.296\n", nullptr)), {});
    tools::ToolTable table = c.toolTableEdits().table();
    ASSERT_EQ(table.size(), 16u) << "one row per pocket of the magazine";
    EXPECT_EQ(table.find(16)->pocket, 16);
    EXPECT_DOUBLE_EQ(table.find(1)->offset(tools::kZ), -53.677);
    EXPECT_DOUBLE_EQ(table.find(2)->offset(tools::kZ), -41.296);
    EXPECT_EQ(tools::formatToolEntry(*table.find(3)), "T3 P3 Z0");
    EXPECT_FALSE(c.toolTableEdits().changed());
}

TEST(ToolData, ADifferentValueInParamsTomlIsSaidAndTheTableWins) {
    config::MachineConfig cfg = load(machineFolder("mismatch", "930 = -50\n931 = -40\n", "T1 P1 Z-52\nT2 P2 Z-40\n"));
    ASSERT_EQ(cfg.warnings.size(), 1u);
    EXPECT_THAT(cfg.warnings[0], HasSubstr("params.toml: warning: parameter 930 (T1 Z) is -50 but "));
    EXPECT_THAT(cfg.warnings[0], HasSubstr("tool.tbl:1 says -52; the tool table is used"));
    controller::Controller c(std::move(cfg), {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -52.0);
}

TEST(ToolData, ABadLineOfTheFoldersTableIsAWarningAndTheMachineLoads) {
    config::MachineConfig cfg = load(machineFolder("bad-line", "", "T1 P1 Z-50\nT2 P1 Z-40\n"));
    ASSERT_EQ(cfg.warnings.size(), 1u);
    EXPECT_THAT(cfg.warnings[0], HasSubstr("tool.tbl:2:1: error: pocket 1 already holds a tool (line 1)"));
    ASSERT_TRUE(cfg.toolTable);
    EXPECT_EQ(cfg.toolTable->size(), 1u);
}

TEST(ToolData, TouchOffSavedSurvivesAReloadWithTheCommentsAndParamsTomlAgrees) {
    fs::path folder = machineFolder("reload", "930 = -50\n", kToolTable);
    {
        controller::Controller c(load(folder), {});
        ASSERT_TRUE(c.loadMdi({"G53 Z-80", "#1431 = -41.5"}));
        ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
        Message why;
        ASSERT_TRUE(c.toolTableEdits().touchOffTool(0.0, &why)) << why; // G54 Z is 0: T1's Z becomes -80
        ASSERT_TRUE(c.toolTableEdits().changed());
        ASSERT_EQ(controller::saveToolTable(c, config::MachineFolder(folder)), std::nullopt);
        EXPECT_FALSE(c.toolTableEdits().changed());
    }
    EXPECT_EQ(readText(folder / "tool.tbl"), "; the router's tools\n"
                                             "T1 P1 Z-80 ;roughing {rpm=18000 teeth=3 type=flat}\n"
                                             "T2 P2 Z-41.5\n"
                                             "T20 P20 Z-30 ;virtual: changed by hand\n"
                                             "T50 P50 Z1 ;kept, though the M350 has no offset for it\n");
    EXPECT_THAT(readText(folder / "params.toml"), HasSubstr("930 = -80\n"))
        << "the value params.toml lists follows, so the two files agree";
    EXPECT_THAT(readText(folder / "params.toml"), testing::Not(HasSubstr("931")))
        << "nothing is added to params.toml: tool.tbl is the one read";
    config::MachineConfig again = load(folder);
    EXPECT_TRUE(again.warnings.empty()) << again.warnings.front();
    controller::Controller c(std::move(again), {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -80.0);
    EXPECT_DOUBLE_EQ(c.parameter(931), -41.5);
    EXPECT_EQ(*c.toolTableEdits().table().find(1)->teeth, 3);
}

// Saves in a child process that the hook kills with SIGKILL, as a crash or a power cut would.
void killedSave(const fs::path& folder, bool duringChunks) {
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        controller::Controller c(load(folder), {});
        c.setParameter(930, -99.0);
        files::AtomicWriteHooks hooks;
        if (duringChunks) hooks.afterChunk = [](std::size_t) { raise(SIGKILL); };
        else hooks.beforeRename = [] { raise(SIGKILL); };
        (void)controller::saveToolTable(c, config::MachineFolder(folder), hooks);
        _exit(0); // not reached: the hook killed us
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
}

TEST(ToolData, ASaveKilledAtAnyPointLeavesTheOldTableWhole) {
    std::string big = kToolTable;
    for (int i = 0; i < 2000; ++i) {
        big += "; a long history of the shop's tools, line " + std::to_string(i) + "\n";
    }
    fs::path folder = machineFolder("killed", "", big.c_str());
    killedSave(folder, true);
    EXPECT_EQ(readText(folder / "tool.tbl"), big) << "killed while the temp file was half written";
    killedSave(folder, false);
    EXPECT_EQ(readText(folder / "tool.tbl"), big) << "killed after the temp was synced, before the rename";
    controller::Controller c(load(folder), {});
    EXPECT_DOUBLE_EQ(c.parameter(930), -50.0);
}

} // namespace
