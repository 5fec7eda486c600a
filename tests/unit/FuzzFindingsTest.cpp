// Regressions for what the libFuzzer targets of tests/fuzz found; each input is also kept in
// tests/fuzz/corpus/<target>/found-* so that the fuzzers start from it.
#include "FileText.h"
#include "RunProgram.h"

#include "core/check/StaticCheck.h"
#include "core/config/MachineConfig.h"

#include "core/gcode/Dialect.h"

#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <string>

namespace m350 {
namespace {

using test::bundledMachine;

std::string joined(const std::vector<gcode::Diagnostic>& diagnostics) {
    std::string out;
    for (const gcode::Diagnostic& d : diagnostics) {
        out += gcode::formatDiagnostic(d) + "\n";
    }
    return out;
}

std::vector<gcode::Diagnostic> checkWithoutRunning(const controller::Controller& controller) {
    const config::MachineConfig machine = controller.config();
    return check::StaticCheck(controller.program(), *machine.dialect, machine.callCodes).findings();
}

// evaluator found-m-code-beyond-int: `M9999999930` saturates to INT_MAX, and the handler number
// O(10000 + code) overflowed (UBSan: signed integer overflow in the static check and the run).
TEST(FuzzFindingsTest, HandlerProgramOfAHugeOrNegativeCodeIsNone) {
    const gcode::Dialect& m350 = gcode::Dialect::m350();
    EXPECT_EQ(m350.handlerProgram('M', 150), 10150);
    EXPECT_EQ(m350.handlerProgram('G', 81), 9081);
    EXPECT_EQ(m350.handlerProgram('M', 99989999), 99999999);
    EXPECT_FALSE(m350.handlerProgram('M', 99990000));
    EXPECT_FALSE(m350.handlerProgram('M', INT_MAX));
    EXPECT_FALSE(m350.handlerProgram('G', INT_MAX));
    EXPECT_FALSE(m350.handlerProgram('M', -5)); // not O9995, a G handler
    EXPECT_FALSE(gcode::Dialect::fanuc().handlerProgram('M', 150));
}

TEST(FuzzFindingsTest, MCodeBeyondIntIsCheckedAndAlarmsWithoutOverflow) {
    controller::Controller controller(bundledMachine(), {});
    ASSERT_TRUE(controller.loadMdi({"#100=1", "M9999999930"})) << joined(controller.diagnostics());
    checkWithoutRunning(controller);
    const controller::RunReport report = controller.run();
    ASSERT_TRUE(report.alarm);
    EXPECT_EQ(report.alarm->line, 2);
    EXPECT_NE(report.alarm->message.find("no such M code"), std::string::npos) << report.alarm->message;
    EXPECT_EQ(report.alarm->message.find("handler"), std::string::npos) << report.alarm->message;
}

TEST(FuzzFindingsTest, GCodeBeyondIntIsReportedByTheCheck) {
    controller::Controller controller(bundledMachine(), {});
    ASSERT_TRUE(controller.loadMdi({"G9999999930"})) << joined(controller.diagnostics());
    const std::string found = joined(checkWithoutRunning(controller));
    EXPECT_NE(found.find("not a G code this machine knows"), std::string::npos) << found;
}

// evaluator found-spindle-load-huge-move: on a machine with a spindle load model (fanuc-ts27r) a
// move of 1e128 mm ends at a virtual time where adding the sample period changes nothing; the load
// watch sampled that instant forever, growing no memory but never returning to the runaway guard.
TEST(FuzzFindingsTest, SpindleLoadSamplingEndsAfterAMoveBeyondTheClocksResolution) {
    controller::RunSettings settings;
    settings.maxSimTime = 30.0;
    controller::Controller controller(bundledMachine("fanuc-ts27r"), settings);
    const std::string huge = "1" + std::string(128, '0') + ".";
    ASSERT_TRUE(controller.loadMdi({"G90 G01 X" + huge + " F500", "M30"})) << joined(controller.diagnostics());
    const controller::RunReport report = controller.run();
    ASSERT_TRUE(report.alarm);
    EXPECT_EQ(report.alarm->line, 1) << report.alarm->message;
    EXPECT_LE(report.simTime, 30.0 + 1e-9) << report.alarm->message;
}

// evaluator found-pclos-first-statement: a PCLOS (or POPEN) before any DPRNT looked up its items
// as statements[0] of an empty table (UBSan: reference binding to null pointer).
TEST(FuzzFindingsTest, PclosBeforeAnyDprntRunsWithoutReadingAStatementTable) {
    controller::Controller controller(bundledMachine("fanuc-ts27r"), {});
    ASSERT_TRUE(controller.loadMdi({"PCLOS", "POPEN", "PCLOS", "M30"})) << joined(controller.diagnostics());
    const controller::RunReport report = controller.run();
    EXPECT_EQ(report.status, controller::RunStatus::Ok) << (report.alarm ? report.alarm->message : "");
}

// A fresh machine folder with only a machine.toml, for a params.toml under test.
std::filesystem::path plainMachineFolder(const char* name) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    test::writeText(folder / "machine.toml", "name = \"plain\"\n");
    return folder;
}

// machine-folder found-table-header-control-character: a params.toml table header whose key starts
// with a character no key may start with stopped the sanitizer builds on an assertion inside
// toml++ 3.3.0 (abort); it is a config error naming the file, line and column, as in a release build.
TEST(FuzzFindingsTest, ATableHeaderWithNoKeyIsAConfigErrorNotAnAbort) {
    namespace fs = std::filesystem;
    const fs::path folder = plainMachineFolder("m350-fuzz-table-header");
    const std::vector<std::pair<std::string, std::string>> headers = {
        {"[params]\n61 = 3000\n[\t\x0e]\n", ":3:3"}, {"[ !]\n", ":1:3"}, {"[[[a]]]\n", ":1:3"}};
    for (const auto& [text, at] : headers) {
        test::writeText(folder / "params.toml", text);
        auto loaded = config::loadMachineFolder(folder.string());
        ASSERT_TRUE(std::holds_alternative<config::ConfigError>(loaded)) << text;
        const config::ConfigError& error = std::get<config::ConfigError>(loaded);
        EXPECT_EQ(error.where(), (folder / "params.toml").string() + at) << error.message;
        EXPECT_NE(error.message.english().find("key"), std::string::npos) << error.message;
    }
    fs::remove_all(folder);
}

// machine-folder found-presentation-form-after-whitespace: toml++ 3.3.0 classifies a character it
// skips as whitespace with a test that reaches __builtin_unreachable for much of U+00A1-U+0499,
// U+2C6E-U+3067 and U+FB26-U+FEFE (UBSan: "execution reached an unreachable program point"). Outside
// strings and comments no such character is TOML: the file is a config error at it. Inside strings and
// comments, where Chinese punctuation and signs such as ° belong, the file loads.
TEST(FuzzFindingsTest, ANonAsciiCharacterBetweenTokensIsAConfigErrorAtItsPlace) {
    namespace fs = std::filesystem;
    const fs::path folder = plainMachineFolder("m350-fuzz-presentation-form");
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"[params]\n61 = 3000\n \xEF\xB9\x90\n", ":3:2: character '\xEF\xB9\x90' (U+FE50)"},
        {"[params]\n61 = 3000\xE3\x80\x82\n", ":2:10: character '\xE3\x80\x82' (U+3002)"},
        {"[params]\n61 =\xE3\x80\x80" "3000\n", ":2:5: character '\xE3\x80\x80' (U+3000)"},
        {"[params]\n61 = 5s\"\xD0\x96\"\n", ":2:9: character '\xD0\x96' (U+0416)"}}; // found-quote-inside-a-bare-value
    for (const auto& [text, at] : refused) {
        test::writeText(folder / "params.toml", text);
        auto loaded = config::loadMachineFolder(folder.string());
        ASSERT_TRUE(std::holds_alternative<config::ConfigError>(loaded)) << text;
        const config::ConfigError& error = std::get<config::ConfigError>(loaded);
        const std::string expected = (folder / "params.toml").string() + at;
        EXPECT_EQ((error.where() + ": " + error.message.english()).substr(0, expected.size()), expected);
    }
    test::writeText(folder / "params.toml",
                    "\xEF\xBB\xBF# \xE4\xB8\xBB\xE8\xBD\xB4\xE3\x80\x82\n[params]\n61 = 3000 # \xC2\xB1" "5\xC2\xB0\xEF\xB9\x90\n");
    auto loaded = config::loadMachineFolder(folder.string());
    ASSERT_FALSE(std::holds_alternative<config::ConfigError>(loaded)) << std::get<config::ConfigError>(loaded).message;
    fs::remove_all(folder);
}

} // namespace
} // namespace m350
