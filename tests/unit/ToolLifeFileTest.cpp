// toollife.txt: the round trip, a bad line reported with file:line:col and skipped while the rest
// loads, skipped lines kept through a save, groups refused whole, the machine folder's warnings,
// an unreadable file refused, and a killed save leaving the old file.
#include "core/config/MachineConfig.h"
#include "core/config/MachineFolder.h"
#include "core/tools/ToolLifeFile.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace m350;
namespace fs = std::filesystem;

constexpr const char* kTwoGroups = "gs 1\nignore 200\nltm minutes\n"
                                   "group 1 life 3 count\ntool 11 h 11 d 31 used 2\ntool 12 h 12 d 32 used 0\n"
                                   "group 2 life 1 minutes\ntool 21 h 21 d 41 used 7\n";

std::vector<std::string> issueTexts(const tools::ParsedToolLife& parsed) {
    std::vector<std::string> texts;
    for (const tools::LifeFileIssue& issue : parsed.issues) {
        texts.push_back(issue.text());
    }
    return texts;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path freshMachine(const std::string& name) {
    // the process id in the name: test runs of other checkouts share /tmp
    fs::path folder = fs::path(::testing::TempDir()) / ("m350_toollife_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::copy(config::bundledMachinesDirectory() + "/fanuc-0i", folder);
    return folder;
}

} // namespace

TEST(ToolLifeFile, TheDataRoundTrip) {
    tools::ParsedToolLife parsed = tools::parseToolLife(kTwoGroups, "toollife.txt");
    ASSERT_TRUE(parsed.issues.empty()) << issueTexts(parsed)[0];
    const tools::LifeData& data = parsed.data;
    EXPECT_EQ(data.gs, 1);
    EXPECT_EQ(data.ignoreNumber, 200);
    EXPECT_EQ(data.defaultKind, tools::LifeKind::Minutes);
    ASSERT_EQ(data.groups.size(), 2u);
    EXPECT_EQ(data.group(1)->tools[0].used, 2);
    EXPECT_EQ(data.group(2)->lifeUnits(), 15);
    tools::ParsedToolLife back = tools::parseToolLife(tools::formatToolLife(data), "toollife.txt");
    EXPECT_TRUE(back.issues.empty());
    EXPECT_EQ(tools::formatToolLife(back.data), tools::formatToolLife(data));
}

TEST(ToolLifeFile, EachBadLineIsReportedAtItsColumnAndTheRestLoads) {
    const std::string text = "gs 0\n"
                             "group 1 life 3 count\n"
                             "tool 11 h 11 d x used 0\n"          // 3: d's value
                             "tool 12 h 12 d 32 used 0 extra\n"   // 4: an unknown word
                             "tool 13 h 13 d 33 used 1\n"
                             "group 2 life 5 hours\n"             // 6: the kind; its tools go with it
                             "tool 21 h 21 d 41 used 0\n"         // 7
                             "  tool 13 h 1 d 1 used 0\n"         // 8: orphan (group 2 was refused)
                             "group 3 life 2 count\n"
                             "tool 31 h 0 d 0 used 0\n"
                             "tool 31 h 1 d 1 used 0\n"           // 11: twice in the group
                             "ignore 0\n";                        // 12
    tools::ParsedToolLife parsed = tools::parseToolLife(text, "m/toollife.txt");
    EXPECT_EQ(issueTexts(parsed),
              (std::vector<std::string>{
                  "m/toollife.txt:3:16: error: d must be a whole number from 0 to 999, not 'x' (line skipped)",
                  "m/toollife.txt:4:26: error: unknown word 'extra' (line skipped)",
                  "m/toollife.txt:6:16: error: the life is counted in 'count' or 'minutes', not 'hours' (line skipped)",
                  "m/toollife.txt:7:1: error: a tool line must follow its 'group' line (line skipped)",
                  "m/toollife.txt:8:3: error: a tool line must follow its 'group' line (line skipped)",
                  "m/toollife.txt:11:6: error: T31 is already in group 3 (line skipped)",
                  "m/toollife.txt:12:8: error: ignore must be a whole number from 1 to 9999, not '0' (line skipped)"}));
    ASSERT_EQ(parsed.data.groups.size(), 2u);
    ASSERT_EQ(parsed.data.group(1)->tools.size(), 1u);
    EXPECT_EQ(parsed.data.group(1)->tools[0].tool, 13);
    EXPECT_EQ(parsed.data.group(1)->tools[0].used, 1);
    EXPECT_EQ(parsed.data.group(3)->tools.size(), 1u);
    EXPECT_EQ(parsed.data.ignoreNumber, 100); // the bad setting left the default
    EXPECT_EQ(parsed.data.unreadLines.size(), 7u);
    EXPECT_EQ(parsed.issues[0].line, 3u);
    EXPECT_EQ(parsed.issues[0].column, 16u);
}

TEST(ToolLifeFile, GroupsWithoutToolsOrBeyondTheCapacityAreSkippedWithTheirLines) {
    tools::ParsedToolLife parsed = tools::parseToolLife("gs 3\n; c\ngroup 4 life 3 minutes\n"
                                                        "group 5 life 2 count\ntool 1 h 0 d 0 used 0\n"
                                                        "tool 2 h 0 d 0 used 0\ntool 3 h 0 d 0 used 0\n"
                                                        "group 6 life 2 count\ntool 9 h 0 d 0 used 1\n",
                                                        "f");
    EXPECT_EQ(issueTexts(parsed),
              (std::vector<std::string>{"f:3:1: error: group 4 has no tools (line skipped)",
                                        "f:4:1: error: group 5 has 3 tools, more than a group holds (GS1/GS2 = 1/1: "
                                        "128 groups of 2 tools) (line skipped)"}));
    ASSERT_EQ(parsed.data.groups.size(), 1u);
    EXPECT_EQ(parsed.data.groups[0].number, 6);
    // group 5 with its three tools stays in the file, as comments
    EXPECT_EQ(parsed.data.unreadLines.size(), 5u);
}

TEST(ToolLifeFile, SkippedLinesSurviveASaveAsCommentsAndAreNotReportedAgain) {
    tools::ParsedToolLife parsed =
        tools::parseToolLife("group 1 life 3 count\ntool 11 h 11 d 31 used 0 extra\ntool 12 h 12 d 32 used 0\n", "f");
    ASSERT_EQ(parsed.issues.size(), 1u);
    parsed.data.group(1)->tools[0].used = 2; // what a run counted
    const std::string saved = tools::formatToolLife(parsed.data);
    EXPECT_NE(saved.find("tool 12 h 12 d 32 used 2\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("\n; not read: tool 11 h 11 d 31 used 0 extra\n"), std::string::npos) << saved;
    tools::ParsedToolLife again = tools::parseToolLife(saved, "f");
    EXPECT_TRUE(again.issues.empty());
    EXPECT_EQ(again.data.unreadLines, parsed.data.unreadLines);
    EXPECT_EQ(tools::formatToolLife(again.data), saved);
}

TEST(ToolLifeFile, TheMachineFolderLoadsTheGoodLinesAndWarnsOfTheBadOnes) {
    fs::path folder = freshMachine("folder");
    std::ofstream(folder / tools::kToolLifeFile) << "group 1 life 3 count\ntool 11 h 1 d 1 used 1\n"
                                                    "group 1 life 2 count\n";
    auto loaded = config::loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const config::MachineConfig& config = std::get<config::MachineConfig>(loaded);
    EXPECT_EQ(config.toolLife.group(1)->tools[0].used, 1);
    ASSERT_EQ(config.toolLifeIssues.size(), 1u);
    EXPECT_EQ(config.toolLifeIssues[0].line, 3u);
    EXPECT_EQ(config.toolLifeIssues[0].column, 7u);
    const std::string expected =
        (folder / tools::kToolLifeFile).string() + ":3:7: error: group 1 is given twice (line skipped)";
    EXPECT_NE(std::find(config.warnings.begin(), config.warnings.end(), expected), config.warnings.end());
    fs::remove_all(folder);
}

TEST(ToolLifeFile, AFileThatCannotBeReadStopsTheMachineFromLoading) {
    fs::path folder = freshMachine("unreadable");
    fs::create_directory(folder / tools::kToolLifeFile); // exists, but no file to read
    auto loaded = config::loadMachineFolder(folder.string());
    ASSERT_TRUE(std::holds_alternative<config::ConfigError>(loaded));
    EXPECT_EQ(std::get<config::ConfigError>(loaded).file, (folder / tools::kToolLifeFile).string());
    EXPECT_EQ(std::get<config::ConfigError>(loaded).message, "cannot read the file: it is a folder, not a regular file");
    fs::remove_all(folder);
}

TEST(ToolLifeFile, ASaveKilledBeforeTheRenameLeavesTheOldFile) {
    fs::path folder = freshMachine("killed");
    tools::LifeData data = tools::parseToolLife(kTwoGroups, "f").data;
    ASSERT_FALSE(config::MachineFolder(folder).saveToolLife(data));
    const std::string before = readText(folder / tools::kToolLifeFile);
    data.group(1)->tools[0].used = 3;
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        files::AtomicWriteHooks hooks;
        hooks.beforeRename = [] { raise(SIGKILL); };
        config::MachineFolder(folder).saveToolLife(data, hooks);
        _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(readText(folder / tools::kToolLifeFile), before);
    ASSERT_FALSE(config::MachineFolder(folder).saveToolLife(data));
    EXPECT_EQ(tools::parseToolLife(readText(folder / tools::kToolLifeFile), "f").data.group(1)->tools[0].used, 3);
    fs::remove_all(folder);
}
