// exercise.toml read through core/training/ExerciseFile.h: every mistake an author makes is refused
// at file:line:col with what is wrong; a sound file gives the exercise; the attempt's machine folder
// is the bundled one with the exercise's changes and the forks where the bundled params put them.
#include "core/config/MachineConfig.h"
#include "core/training/ExerciseFile.h"
#include "core/training/ExerciseMachine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

namespace m350::test {

namespace {

namespace fs = std::filesystem;

const char* kSound = R"toml(level = 2
time_limit = 300
machine = "m350-linear16"
[title]
zh_CN = "换刀"
en = "A change"
[task]
zh_CN = "换 T2。"
en = "Change to T2."
[parameters]
831 = 112
[[lines]]
file = "slib-g.nc"
line = 3
text = "(changed)"
[[checks]]
id = "t2"
kind = "spindle_tool"
expect = 2
[checks.why]
zh_CN = "主轴上不是 T2。"
en = "The spindle does not hold T2."
)toml";

class ExerciseFileTest : public testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("m350-exercise-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_ / "ex");
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::variant<training::Exercise, training::ExerciseError> load(const std::string& text) {
        std::ofstream(folder_ / "ex" / "exercise.toml") << text;
        return training::loadExercise((folder_ / "ex").string(), config::bundledMachinesDirectory());
    }
    // The refusal's "file:line:col: english".
    std::string refusal(const std::string& text) {
        auto loaded = load(text);
        auto* error = std::get_if<training::ExerciseError>(&loaded);
        return error ? error->where() + ": " + error->words.english() : std::string("loaded");
    }
    std::string replaced(std::string text, const std::string& from, const std::string& to) {
        text.replace(text.find(from), from.size(), to);
        return text;
    }
    fs::path folder_;
};

} // namespace

TEST_F(ExerciseFileTest, ASoundExerciseLoads) {
    auto loaded = load(kSound);
    ASSERT_TRUE(std::holds_alternative<training::Exercise>(loaded)) << refusal(kSound);
    const auto& e = std::get<training::Exercise>(loaded);
    EXPECT_EQ(e.name, "ex");
    EXPECT_EQ(e.level, 2);
    EXPECT_EQ(e.parameters.at(831), 112.0);
    ASSERT_EQ(e.checks.size(), 1u);
    EXPECT_EQ(e.checks[0].kind, training::Check::Kind::SpindleTool);
    EXPECT_EQ(e.checks[0].why.chinese, "主轴上不是 T2。");
}

TEST_F(ExerciseFileTest, MistakesAreRefusedAtTheirPlace) {
    const std::string file = (folder_ / "ex" / "exercise.toml").string();
    EXPECT_EQ(refusal(replaced(kSound, "kind = \"spindle_tool\"", "kind = \"spindle\"")),
              file + ":18:8: unknown check kind 'spindle' (known: spindle_tool, pocket_tool, no_alarm, alarm, no_crash, parameter, "
                     "tool_offset, variable, output, responded, file_line, finished, time_used)");
    EXPECT_EQ(refusal(replaced(kSound, "m350-linear16", "m350-nowhere")),
              file + ":3:11: no bundled machine folder 'm350-nowhere' in " + config::bundledMachinesDirectory());
    EXPECT_EQ(refusal(replaced(kSound, "level = 2", "level = [2")).substr(0, file.size() + 3), file + ":2:"); // toml++ finds it there
    EXPECT_EQ(refusal(replaced(kSound, "time_limit = 300", "time_limt = 300")).substr(0, file.size() + 8),
              file + ":2:1: un");
    EXPECT_EQ(refusal(replaced(kSound, "file = \"slib-g.nc\"", "file = \"slib-x.nc\"")).rfind(file + ":13:8: the machine folder has no file 'slib-x.nc'", 0), 0u);
    EXPECT_NE(refusal(replaced(kSound, "en = \"The spindle does not hold T2.\"\n", "")).find("'en' is missing"), std::string::npos);
    EXPECT_NE(refusal(replaced(kSound, "expect = 2", "expect = 2\npocket = 3")).find("unknown key 'pocket' in checks"), std::string::npos);
    const std::string twice = std::string(kSound) + "[[checks]]\nid = \"t2\"\nkind = \"no_crash\"\n[checks.why]\nzh_CN = \"撞了\"\nen = \"Crashed\"\n";
    EXPECT_NE(refusal(twice).find("check 't2' is already defined at line 16"), std::string::npos) << refusal(twice);
}

TEST_F(ExerciseFileTest, TheAttemptsMachineIsTheBundledOneWithTheChanges) {
    auto loaded = load(kSound);
    ASSERT_TRUE(std::holds_alternative<training::Exercise>(loaded));
    const fs::path machine = folder_ / "machine";
    ASSERT_FALSE(training::prepareExerciseMachine(std::get<training::Exercise>(loaded), config::bundledMachinesDirectory(),
                                                  machine.string()));
    auto config = config::loadMachineFolder(machine.string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(config));
    const auto& c = std::get<config::MachineConfig>(config);
    EXPECT_EQ(c.parameters.get(831), 112.0);
    ASSERT_GE(c.magazine.forks.size(), 2u);
    EXPECT_EQ(c.magazine.forks[1][0], 110.0) << "the fork stands where the bundled params put it";
    std::ifstream library(machine / "slib-g.nc");
    std::string line;
    for (int n = 0; n < 3; ++n) {
        std::getline(library, line);
    }
    EXPECT_EQ(line, "(changed)");
}

} // namespace m350::test
