// Golden tests: one folder per behaviour under tests/golden/ (see README.md there). Each folder is
// one test case, found at run time: m350-sim runs the folder's program with the folder's options,
// in the folder, and its whole JSON output must equal expected.json (numbers within 1e-9).
// M350_REBASELINE=1 writes the output to expected.json instead, for review.
#include "tests/cli/SimProcess.h"
#include "tests/golden/JsonDiff.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kMainProgram = "input.nc";

fs::path goldenDirectory() {
    return fs::path(M350_GOLDEN_DIR);
}

bool rebaselining() {
    const char* flag = std::getenv("M350_REBASELINE");
    return flag != nullptr && std::string(flag) == "1";
}

// A folder is a case when it holds the program or says how to run m350-sim without one (mdi).
std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(goldenDirectory(), ec)) {
        const fs::path& folder = entry.path();
        if (entry.is_directory() && (fs::exists(folder / kMainProgram) || fs::exists(folder / "args"))) {
            names.push_back(folder.filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> readArgs(const fs::path& file) {
    std::vector<std::string> lines;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        if (line.find_first_not_of(" \t") != std::string::npos) {
            lines.push_back(line);
        }
    }
    return lines;
}

// The m350-sim command line of a case folder (see README.md for the `args` format).
std::vector<std::string> commandLine(const fs::path& folder) {
    std::vector<std::string> lines = readArgs(folder / "args");
    std::vector<std::string> argv;
    std::size_t rest = 0;
    if (!lines.empty() && lines.front() == "mdi") {
        argv = {"mdi"};
        rest = 1;
    } else if (!lines.empty() && (lines.front() == "run" || lines.front() == "check")) {
        argv = {lines.front(), kMainProgram};
        rest = 1;
    } else {
        argv = {"run", kMainProgram};
    }
    argv.insert(argv.end(), lines.begin() + static_cast<std::ptrdiff_t>(rest), lines.end());
    bool hasConfig = std::any_of(argv.begin(), argv.end(), [](const std::string& a) {
        return a == "--config" || a.rfind("--config=", 0) == 0;
    });
    if (!hasConfig && fs::is_directory(folder / "config")) {
        argv.insert(argv.end(), {"--config", "config"});
    }
    return argv;
}

// The exit status the contract pairs with each status.
int exitStatusFor(const std::string& status) {
    if (status == "ok") {
        return 0;
    }
    if (status == "alarm") {
        return 1;
    }
    return 2;
}

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) {
        out += (out.empty() ? "" : " ") + (w.find(' ') == std::string::npos ? w : "'" + w + "'");
    }
    return out;
}

std::string pretty(const json& j) {
    return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

class GoldenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenTest, OutputMatchesExpectedJson) {
    const fs::path folder = goldenDirectory() / GetParam();
    const std::vector<std::string> argv = commandLine(folder);
    const m350::testing::ProcessResult result =
        m350::testing::runProcess(M350_SIM_PATH, argv, folder.string());
    const std::string context = "case " + folder.string() + "\ncommand: m350-sim " + joined(argv) +
                                "\nexit status: " + std::to_string(result.exitStatus) + "\nstderr:\n" +
                                result.err;

    json actual;
    try {
        actual = json::parse(result.out);
    } catch (const json::exception& e) {
        FAIL() << "stdout is not one JSON document (" << e.what() << "):\n" << result.out << "\n" << context;
    }
    ASSERT_TRUE(actual.is_object()) << "stdout is not a JSON object:\n" << result.out << "\n" << context;
    EXPECT_EQ(result.exitStatus, exitStatusFor(actual.value("status", std::string())))
        << "exit status does not match \"status\"\n"
        << context;

    const fs::path expectedFile = folder / "expected.json";
    if (rebaselining()) {
        std::ofstream(expectedFile, std::ios::trunc) << pretty(actual);
        GTEST_SKIP() << "rebaselined " << expectedFile.string() << ": review it before committing";
    }
    ASSERT_TRUE(fs::exists(expectedFile)) << "no expected.json: run with M350_REBASELINE=1, then review it\n"
                                          << context;
    json expected;
    try {
        expected = json::parse(std::ifstream(expectedFile));
    } catch (const json::exception& e) {
        FAIL() << expectedFile.string() << " is not valid JSON: " << e.what();
    }
    const std::vector<std::string> differences = m350::testing::jsonDifferences(expected, actual);
    if (!differences.empty()) {
        std::ostringstream report;
        for (const std::string& d : differences) {
            report << "  " << d << "\n";
        }
        ADD_FAILURE() << "output differs from expected.json:\n"
                      << report.str() << context << "actual output:\n"
                      << pretty(actual);
    }
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenTest, ::testing::ValuesIn(caseNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return m350::testing::testNameFor(info.param);
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenTest);

} // namespace
