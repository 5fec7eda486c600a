// No input may crash or hang the simulator: random programs made of the language's own pieces
// must end in ok, an alarm or a syntax error, with the alarm located in the program.
#include "core/config/MachineConfig.h"
#include "core/controller/Controller.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace m350;

const std::vector<std::string> kPieces = {
    "#1", "#[", "]", "[", "#1300", "#1520", "#1552", "#3000", "#0", "=", "==", "EQ", "NE", "+", "-", "*", "/",
    "IF", "GOTO", "GOTO1", "WHILE", "DO1", "END1", "DO2", "END2", "THEN", "N1", "N2", "G1", "G0", "G53", "G04",
    "G65", "M98", "M99", "P1", "P2", "L3", "X", "Y-", "Z1.5", "F100", "T2", "M3", "M5", "M30", "SIN[", "SQRT[",
    "ATAN[", ",", "1", "0", "2.5", "-1", "(c)", "(", ")", "//", ";", "O1", "O2", "AND", "MOD", "%", "（", " ",
    "1e999", "99999999999999999999", "#99999"};

// A file of this process only: the simulator maps the program it reads, and another test run
// rewriting a shared temp file under that mapping (other worktrees' ctest) kills it with SIGBUS.
std::string processTempFile(const std::string& name) {
    return (std::filesystem::path(testing::TempDir()) / (std::to_string(::getpid()) + "-" + name)).string();
}

std::string randomProgram(std::mt19937& rng) {
    std::uniform_int_distribution<std::size_t> piece(0, kPieces.size() - 1);
    std::uniform_int_distribution<int> lineLength(0, 9);
    std::uniform_int_distribution<int> lineCount(1, 12);
    std::string text;
    for (int line = lineCount(rng); line > 0; --line) {
        for (int n = lineLength(rng); n > 0; --n) {
            text += kPieces[piece(rng)];
        }
        text += '\n';
    }
    return text;
}

void runOne(const std::string& text, const gcode::Dialect& dialect, const std::string& path) {
    std::ofstream(path, std::ios::trunc) << text;
    config::MachineConfig cfg;
    cfg.dialect = &dialect;
    cfg.parameters.set(801, 16);
    controller::RunSettings settings;
    settings.maxSimTime = 0.05;
    controller::Controller controller(std::move(cfg), settings);
    bool runnable = controller.loadFile(path);
    controller::RunReport report = controller.run();
    if (!runnable) {
        EXPECT_EQ(report.status, controller::RunStatus::Error) << text;
        return;
    }
    ASSERT_NE(report.status, controller::RunStatus::Error) << text;
    if (report.status == controller::RunStatus::Alarm) {
        ASSERT_TRUE(report.alarm.has_value());
        EXPECT_FALSE(report.alarm->message.empty()) << text;
        EXPECT_GT(report.alarm->line, 0u) << text;
    }
}

TEST(Robustness, RandomProgramsNeverCrashOrHangInEitherDialect) {
    std::mt19937 rng(350);
    std::string path = processTempFile("robustness.nc");
    for (int i = 0; i < 1500; ++i) {
        std::string text = randomProgram(rng);
        runOne(text, gcode::Dialect::m350(), path);
        runOne(text, gcode::Dialect::fanuc(), path);
        if (HasFatalFailure()) {
            return;
        }
    }
}

TEST(Robustness, ArbitraryBytesAreReportedNotCrashedOn) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> byte(0, 255);
    std::string path = processTempFile("bytes.nc");
    for (int i = 0; i < 300; ++i) {
        std::string text;
        for (int n = 0; n < 200; ++n) {
            text.push_back(static_cast<char>(byte(rng)));
        }
        runOne(text, gcode::Dialect::m350(), path);
    }
}

} // namespace
