// Issue 13: every write of a machine folder is atomic. A child process saves the folder in a loop
// (parameters, the tool table with its Z parameters, tool life data, the system log, mdi.nc) and is
// killed with SIGKILL at a random moment, 200 times: the folder always loads, each file as one
// whole state, the old or the new, never a mix or a loss; the temp files killed writers leave are
// ignored by the loader and removed by the next save.
#include "FileText.h"
#include "RunProgram.h"

#include "core/config/MachineFolder.h"
#include "core/controller/ToolTableSave.h"
#include "core/files/AtomicFile.h"
#include "core/files/LastGoodCopy.h"
#include "core/files/SystemLog.h"
#include "core/tools/ToolLifeFile.h"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace m350 {
namespace {

namespace fs = std::filesystem;

constexpr int kFirstParam = 61; // params 61-64 are saved together: they must always agree

using test::readText;
using test::writeText;

fs::path scratchFolder(const std::string& name) {
    // tmpfs when there is one: the kills test the order of writes, not the disk's speed
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::path(testing::TempDir());
    fs::path folder = base / ("m350-crash-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

std::unique_ptr<files::SystemLog> openLog(const fs::path& folder) {
    auto log = std::make_unique<files::SystemLog>((folder / "system-log.tsv").string(), 100000);
    Message error;
    EXPECT_TRUE(log->load(&error)) << error;
    return log;
}

// T1's Z offset for version v (never 0: a tool with no Z leaves the table).
double toolZ(int v) { return -100.0 - v; }
int versionOfZ(double z) { return static_cast<int>(-z - 100.0); }

// One save of the whole folder as version v, in the order the panel's writers would do it; false
// when a write failed.
bool saveVersion(const fs::path& folder, controller::Controller& controller, files::SystemLog& log, int v) {
    std::map<int, double> params;
    for (int n = kFirstParam; n < kFirstParam + 4; ++n) {
        params[n] = 100 + v;
    }
    if (config::MachineFolder(folder).saveParameters(params) || !controller.setParameter(930, toolZ(v)) ||
        controller::saveToolTable(controller, config::MachineFolder(folder))) { // tool.tbl, then its Z into params 930-945
        return false;
    }
    tools::LifeData life;
    life.putGroup({1, 100 + v, tools::LifeKind::Count, {{1, 0, 0, 0}}});
    Message error;
    return !config::MachineFolder(folder).saveToolLife(life) &&
           log.append({"2026-11-24 05:00:00", "save", std::to_string(v)}, &error) &&
           !files::writeFileAtomically(folder / "mdi.nc", "G0 X" + std::to_string(v) + "\n");
}

// The version each file holds, in the order saveVersion writes them.
struct FolderState {
    int params = -1, toolTable = -1, toolParams = -1, life = -1, log = -1, mdi = -1;
    std::array<int, 6> inWriteOrder() const { return {params, toolTable, toolParams, life, log, mdi}; }
};

FolderState loadState(const fs::path& folder) {
    FolderState s;
    auto loaded = config::loadMachineFolder(folder.string());
    if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
        ADD_FAILURE() << error->where() << ": " << error->message;
        return s;
    }
    const config::MachineConfig& config = std::get<config::MachineConfig>(loaded);
    for (const std::string& warning : config.warnings) {
        EXPECT_EQ(warning.find("not read"), std::string::npos) << warning;
    }
    EXPECT_TRUE(config.toolLifeIssues.empty());
    s.params = static_cast<int>(config.parameters.get(kFirstParam)) - 100;
    for (int n = kFirstParam + 1; n < kFirstParam + 4; ++n) {
        EXPECT_EQ(config.parameters.get(n), s.params + 100) << "params.toml mixes two saves";
    }
    s.toolParams = versionOfZ(config.parameters.get(930));
    if (config.toolTable && config.toolTable->find(1)) {
        s.toolTable = versionOfZ(config.toolTable->find(1)->offset(tools::kZ));
    }
    if (const tools::LifeGroup* group = config.toolLife.group(1)) {
        s.life = group->life - 100;
    }
    auto log = openLog(folder);
    for (std::size_t i = 0; i < log->entries().size(); ++i) {
        EXPECT_EQ(log->entries()[i].detail, std::to_string(i)) << "the log lost or mixed an entry";
    }
    s.log = static_cast<int>(log->entries().size()) - 1;
    const std::string mdi = readText(folder / "mdi.nc");
    EXPECT_EQ(mdi.rfind("G0 X", 0), 0u) << mdi;
    s.mdi = std::atoi(mdi.c_str() + 4);
    return s;
}

TEST(MachineFolderCrash, AWriterKilledAtRandomLeavesEveryFileOldOrNew) {
    const fs::path folder = scratchFolder("kill");
    writeText(folder / "machine.toml", "name = \"crash\"\ndialect = \"m350\"\n");
    writeText(folder / "params.toml", "[params]\n78 = 1\n800 = 1\n801 = 16\n930 = 0\n");
    {
        auto loaded = config::loadMachineFolder(folder.string());
        ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
        controller::Controller first(std::get<config::MachineConfig>(std::move(loaded)), {});
        auto log = openLog(folder);
        ASSERT_TRUE(saveVersion(folder, first, *log, 0));
    }
    FolderState before = loadState(folder);
    ASSERT_EQ(before.inWriteOrder(), (std::array<int, 6>{0, 0, 0, 0, 0, 0}));

    std::mt19937 random(13);
    std::uniform_int_distribution<int> delayMicroseconds(0, 1500);
    int partial = 0;
    for (int round = 0; round < 200; ++round) {
        int ready[2];
        ASSERT_EQ(::pipe(ready), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::close(ready[0]);
            auto loaded = config::loadMachineFolder(folder.string());
            if (!std::holds_alternative<config::MachineConfig>(loaded)) {
                _exit(3);
            }
            controller::Controller controller(std::get<config::MachineConfig>(std::move(loaded)), {});
            auto log = openLog(folder);
            int v = static_cast<int>(log->entries().size()); // the next version: one entry per save
            // The parent's random delay starts after one whole save, so every round gets work done
            // however slow the machine (an ASan build on a busy CI runner saved under 100 in all).
            if (!saveVersion(folder, controller, *log, v)) {
                _exit(3);
            }
            ++v;
            const char go = 1;
            (void)!::write(ready[1], &go, 1);
            while (saveVersion(folder, controller, *log, v)) {
                ++v;
            }
            _exit(3); // a write failed: the parent sees an exit, not a kill
        }
        ::close(ready[1]);
        char go = 0;
        ASSERT_EQ(::read(ready[0], &go, 1), 1) << "the writer could not load the folder (round " << round << ")";
        ::close(ready[0]);
        std::this_thread::sleep_for(std::chrono::microseconds(delayMicroseconds(random)));
        ::kill(child, SIGKILL);
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the writer stopped by itself: " << status;

        const FolderState after = loadState(folder);
        const auto versions = after.inWriteOrder();
        const auto previous = before.inWriteOrder();
        for (std::size_t i = 0; i < versions.size(); ++i) {
            EXPECT_GE(versions[i], previous[i]) << "round " << round << ": file " << i << " went back (lost a save)";
            if (i > 0) {
                EXPECT_LE(versions[i], versions[i - 1]) << "round " << round << ": file " << i << " is newer than "
                                                        << "a file written before it";
            }
        }
        // The writer saved versions start, start + 1, ...: each file holds the newest one or, after
        // the file it was writing when killed, the one before (or what it held before this writer).
        const int start = before.log + 1; // the writer's first version: one log entry per save
        const int newest = versions.front();
        for (std::size_t i = 0; i < versions.size(); ++i) {
            const int older = newest > start ? newest - 1 : previous[i];
            EXPECT_TRUE(newest < start ? versions[i] == previous[i] : versions[i] == newest || versions[i] == older)
                << "round " << round << ": file " << i << " holds version " << versions[i] << " (newest " << newest
                << ", the writer began at " << start << ")";
        }
        partial += versions.front() != versions.back() ? 1 : 0;
        before = after;
        if (testing::Test::HasFailure()) {
            break;
        }
    }
    EXPECT_GT(partial, 10) << "the kills should land inside a save, not only between saves";
    EXPECT_GE(before.mdi, 200) << "every writer finished at least its first save";

    // A finished save removes the temp files the killed writers left.
    {
        auto loaded = config::loadMachineFolder(folder.string());
        ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
        controller::Controller last(std::get<config::MachineConfig>(std::move(loaded)), {});
        auto log = openLog(folder);
        ASSERT_TRUE(saveVersion(folder, last, *log, static_cast<int>(log->entries().size())));
    }
    for (const char* name : {"params.toml", "tool.tbl", "toollife.txt", "system-log.tsv", "mdi.nc"}) {
        EXPECT_TRUE(files::staleTempFiles(folder / name).empty()) << name;
    }
    fs::remove_all(folder);
}

TEST(MachineFolderCrash, AHandBrokenFileNamesItsLineAndTheLastGoodCopy) {
    const fs::path folder = scratchFolder("broken");
    writeText(folder / "machine.toml", "name = \"broken\"\n");
    ASSERT_EQ(config::MachineFolder(folder).saveParameters({{61, 3000}, {62, 500}}), std::nullopt);
    const std::string good = readText(folder / "params.toml");
    EXPECT_EQ(readText(files::lastGoodPath(folder / "params.toml")), good) << "a save keeps a good copy beside";

    writeText(folder / "params.toml", "[params]\n61 = 3000\n62 = = 500\n");
    auto loaded = config::loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<config::ConfigError>(loaded));
    const config::ConfigError& error = std::get<config::ConfigError>(loaded);
    EXPECT_EQ(error.where(), (folder / "params.toml").string() + ":3:6");
    EXPECT_NE(error.message.english().find("(its last good copy: " + (folder / "params.toml.last-good").string() + ")"),
              std::string::npos)
        << error.message;
    EXPECT_EQ(readText(files::lastGoodPath(folder / "params.toml")), good) << "a broken file never replaces the copy";

    writeText(folder / "params.toml", "[params]\n61 = 2500\n");
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(config::loadMachineFolder(folder.string())));
    EXPECT_EQ(readText(files::lastGoodPath(folder / "params.toml")), "[params]\n61 = 2500\n")
        << "a file fixed by hand that loads is the new good copy";
    fs::remove_all(folder);
}

TEST(MachineFolderCrash, AFolderNeverSavedIntoGetsNoCopies) {
    const fs::path folder = scratchFolder("read-only");
    writeText(folder / "machine.toml", "name = \"plain\"\n");
    writeText(folder / "params.toml", "[params]\n61 = 2500\n");
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(config::loadMachineFolder(folder.string())));
    EXPECT_FALSE(fs::exists(files::lastGoodPath(folder / "params.toml"))) << "loading writes nothing new";
    fs::remove_all(folder);
}

TEST(MachineFolderCrash, ALogLineCutShortIsSkippedAndTheNextAppendRepairsTheFile) {
    const fs::path folder = scratchFolder("log");
    const fs::path file = folder / "system-log.tsv";
    writeText(file, "t1\tstart\tone\nt2\tstop\ttwo\nt3\tsta");
    files::SystemLog log(file.string());
    Message error;
    std::size_t skipped = 0;
    ASSERT_TRUE(log.load(&error, &skipped)) << error;
    EXPECT_EQ(log.entries().size(), 2u);
    EXPECT_EQ(skipped, 1u);
    ASSERT_TRUE(log.append({"t4", "start", "four"}, &error)) << error;
    EXPECT_EQ(readText(file), "t1\tstart\tone\nt2\tstop\ttwo\nt4\tstart\tfour\n");
    ASSERT_TRUE(log.append({"t5", "stop", "five"}, &error)) << error;
    EXPECT_EQ(readText(file), "t1\tstart\tone\nt2\tstop\ttwo\nt4\tstart\tfour\nt5\tstop\tfive\n");
    fs::remove_all(folder);
}

} // namespace
} // namespace m350
