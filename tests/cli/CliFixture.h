#pragma once

// CLI tests: m350-sim run as a user (or a grader's script) runs it, checking the contract of
// README.md "m350-sim": exit status, exactly one JSON object on stdout, `file:line:col: message`
// on stderr, and what each option does.
#include "tests/cli/SimProcess.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace m350::clitest {

namespace fs = std::filesystem;
using m350::testing::ProcessResult;
using nlohmann::json;

inline constexpr int kExitOk = 0;
inline constexpr int kExitAlarm = 1;
inline constexpr int kExitError = 2;
inline constexpr int kExitUsage = 64;
inline constexpr std::size_t kOutputCount = 21; // OUT01..OUT21

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty()) {
            out.push_back(line);
        }
    }
    return out;
}

inline std::set<std::string> keysOf(const json& object) {
    std::set<std::string> keys;
    for (const auto& [key, value] : object.items()) {
        keys.insert(key);
    }
    return keys;
}

inline bool allDigits(const std::string& s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

// Every run and mdi output: the keys README.md lists, each of its type.
inline void expectRunContract(const json& j) {
    ASSERT_TRUE(j.is_object());
    const std::set<std::string> contract{"status",  "alarm",   "vars",     "machine",    "work",       "tool",
                                         "pockets", "outputs", "messages", "sim_time_s", "diagnostics"};
    // and the keys a run has only when it says something: a warning, a tool it is unsure of
    std::set<std::string> keys = keysOf(j);
    for (const char* optional : {"warnings", "tool_unsure"}) {
        if (keys.erase(optional) == 1) {
            const json& said = j[optional];
            for (const json& one : said.is_array() ? said : json::array({said})) {
                EXPECT_EQ(keysOf(one), (std::set<std::string>{"message", "message_id", "arguments"})) << one;
            }
        }
    }
    if (keys.erase("message_ids") == 1) { // the messages by id, one for each, when one has an id
        ASSERT_TRUE(j["message_ids"].is_array());
        EXPECT_EQ(j["message_ids"].size(), j["messages"].size());
        for (const json& one : j["message_ids"]) {
            EXPECT_TRUE(one.is_null() || keysOf(one) == (std::set<std::string>{"message_id", "message_arguments"})) << one;
        }
    }
    EXPECT_EQ(keys, contract);

    ASSERT_TRUE(j.contains("status") && j["status"].is_string());
    const std::string status = j["status"];
    EXPECT_TRUE(status == "ok" || status == "alarm" || status == "error") << status;

    if (j.contains("alarm") && !j["alarm"].is_null()) {
        const json& a = j["alarm"];
        ASSERT_TRUE(a.is_object()) << a;
        std::set<std::string> keys = keysOf(a);
        if (keys.erase("message_id") + keys.erase("message_arguments") > 0) { // an alarm of the message table
            EXPECT_TRUE(a.value("message_id", json()).is_string()) << a;
            EXPECT_TRUE(a.value("message_arguments", json()).is_array()) << a;
        }
        EXPECT_EQ(keys, (std::set<std::string>{"code", "message", "file", "line", "column"}));
        EXPECT_TRUE(a.value("code", json()).is_string()) << a;
        EXPECT_TRUE(a.value("message", json()).is_string()) << a;
        EXPECT_TRUE(a.value("file", json()).is_string()) << a;
        EXPECT_TRUE(a.value("line", json()).is_number_integer()) << a;
        EXPECT_TRUE(a.value("column", json()).is_number_integer()) << a;
    }
    EXPECT_EQ(j.value("alarm", json()).is_null(), status == "ok")
        << "alarm must be null exactly when status is ok";

    if (j.contains("vars")) {
        ASSERT_TRUE(j["vars"].is_object());
        for (const auto& [n, v] : j["vars"].items()) {
            EXPECT_TRUE(allDigits(n)) << n;
            EXPECT_TRUE(v.is_number() || v.is_null()) << n << ": " << v;
        }
    }
    for (const char* frame : {"machine", "work"}) {
        if (!j.contains(frame)) {
            continue;
        }
        EXPECT_EQ(keysOf(j[frame]), (std::set<std::string>{"X", "Y", "Z", "A", "B"})) << frame;
        for (const auto& [axis, v] : j[frame].items()) {
            EXPECT_TRUE(v.is_number()) << frame << "." << axis << ": " << v;
        }
    }
    if (j.contains("tool")) {
        EXPECT_TRUE(j["tool"].is_number_integer()) << j["tool"];
    }
    if (j.contains("pockets")) {
        ASSERT_TRUE(j["pockets"].is_object());
        for (const auto& [pocket, tool] : j["pockets"].items()) {
            EXPECT_TRUE(allDigits(pocket)) << pocket;
            EXPECT_TRUE(tool.is_number_integer() && tool.get<int>() >= 0) << pocket << ": " << tool;
        }
    }
    if (j.contains("outputs")) {
        ASSERT_TRUE(j["outputs"].is_array());
        EXPECT_EQ(j["outputs"].size(), kOutputCount);
        for (const json& level : j["outputs"]) {
            EXPECT_TRUE(level == 0 || level == 1) << level;
        }
    }
    if (j.contains("messages")) {
        ASSERT_TRUE(j["messages"].is_array());
        for (const json& m : j["messages"]) {
            EXPECT_TRUE(m.is_string()) << m;
        }
    }
    if (j.contains("sim_time_s")) {
        EXPECT_TRUE(j["sim_time_s"].is_number() && j["sim_time_s"].get<double>() >= 0) << j["sim_time_s"];
    }
    if (j.contains("diagnostics")) {
        ASSERT_TRUE(j["diagnostics"].is_array());
        for (const json& d : j["diagnostics"]) {
            std::set<std::string> keys = keysOf(d);
            if (keys.count("message_id") == 1) { // a finding of the message table: its id and arguments
                EXPECT_EQ(keys.erase("message_arguments"), 1u) << d;
                keys.erase("message_id");
            }
            EXPECT_EQ(keys, (std::set<std::string>{"file", "line", "column", "severity", "kind", "message"})) << d;
        }
    }
}

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "m350-cli-XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    fs::path write(const std::string& name, const std::string& text) {
        fs::path path = dir_ / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    // Runs m350-sim in the test's scratch folder.
    ProcessResult sim(const std::vector<std::string>& args) {
        return m350::testing::runProcess(M350_SIM_PATH, args, dir_.string());
    }

    // Stdout must hold exactly one JSON object; returns it.
    static json output(const ProcessResult& r) {
        json j;
        try {
            j = json::parse(r.out);
        } catch (const json::exception& e) {
            ADD_FAILURE() << "stdout is not one JSON document (" << e.what() << "):\n"
                          << r.out << "\nstderr:\n"
                          << r.err;
            return json::object();
        }
        EXPECT_TRUE(j.is_object()) << r.out;
        EXPECT_EQ(lines(r.out).size(), 1u) << "one JSON object on one line:\n" << r.out;
        return j;
    }

    // Writes `text` to `file` and runs it; the exit status and "status" must be the given pair.
    json runExpecting(const std::string& file, const char* text, int exitStatus, const std::string& status) {
        write(file, text);
        ProcessResult r = sim({"run", file});
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err;
        json j = output(r);
        EXPECT_EQ(j.value("status", ""), status) << r.out;
        return j;
    }

    fs::path dir_;
};

inline const char* const kEndingProgram = "G00 X1 Y2\nM30\n";
inline const char* const kAlarmProgram = "#1=0\n#2=1/#1\nM30\n";
inline const char* const kSyntaxErrorProgram = "G00 X1\n#1=[2\nM30\n";

} // namespace m350::clitest
