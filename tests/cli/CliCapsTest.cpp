// Issue 13: a 13-byte `N1 M00 / GOTO1` program filled 9.3 GB with messages and trace lines. The
// report keeps the first and last messages and says how many were left out; the trace stays within
// --trace-limit with a trace_truncated line between its first and last lines; DPRNT output within
// --dprnt-limit.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace m350::clitest {

TEST_F(CliTest, AnEndlessStopLoopIsCappedAndSaysSo) {
    write("loop.nc", "N1 M00\nGOTO1\n");
    ProcessResult r = sim({"run", "loop.nc", "--max-sim-time", "2", "--trace", "loop.trace", "--trace-limit", "64K"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", ""), "simulated_time_limit");
    const json& messages = j["messages"];
    ASSERT_EQ(messages.size(), 4001u);
    const std::uint64_t omitted = j.value("messages_omitted", 0ull);
    EXPECT_GT(omitted, 5000u);
    EXPECT_EQ(messages[0], "M00 program stop (loop.nc:1): START pressed (run without an operator)");
    EXPECT_EQ(messages[4000], messages[0]);
    EXPECT_NE(messages[2000].get<std::string>().find(std::to_string(omitted) + " more messages omitted"),
              std::string::npos)
        << messages[2000];

    const std::filesystem::path trace = dir_ / "loop.trace";
    EXPECT_LE(std::filesystem::file_size(trace), 64u * 1024);
    std::ifstream in(trace);
    std::string line;
    std::vector<json> kept;
    while (std::getline(in, line)) {
        kept.push_back(json::parse(line)); // every kept line is whole JSON
    }
    ASSERT_GT(kept.size(), 10u);
    EXPECT_EQ(kept.front().value("type", ""), "pause");
    EXPECT_DOUBLE_EQ(kept.front().value("t", 0.0), 0.0001);
    EXPECT_EQ(kept.back().value("type", ""), "alarm") << "the run's end is kept";
    int notes = 0;
    for (const json& event : kept) {
        if (event.value("type", "") == "trace_truncated") {
            ++notes;
            EXPECT_GT(event.value("omitted_lines", 0), 10000);
            EXPECT_EQ(event.value("limit_bytes", 0), 65536);
        }
    }
    EXPECT_EQ(notes, 1);
}

TEST_F(CliTest, ATraceLimitMustBeAPositiveSize) {
    write("p.nc", "G0 X1\nM30\n");
    EXPECT_EQ(sim({"run", "p.nc", "--trace", "t", "--trace-limit", "0"}).exitStatus, kExitUsage);
    EXPECT_EQ(sim({"run", "p.nc", "--trace", "t", "--trace-limit", "lots"}).exitStatus, kExitUsage);
    ProcessResult fine = sim({"run", "p.nc", "--trace", "t", "--trace-limit", "1M"});
    EXPECT_EQ(fine.exitStatus, kExitOk) << fine.err;
    EXPECT_FALSE(output(fine).contains("messages_omitted")) << "the key appears only when messages were left out";
}

// --dprnt-limit bounds what dprnt.txt keeps as --trace-limit bounds the trace: 500 records of 16
// bytes in a 2K limit keep the first records, the last ones and a line saying what was left out.
TEST_F(CliTest, ADprntLimitKeepsTheFirstAndTheLastRecords) {
    write("count.nc", "POPEN\n#1=1\nWHILE[#1LE500]DO1\nDPRNT[RECORD*#1[40]]\n#1=#1+1\nEND1\nPCLOS\nM30\n");
    const std::string fanuc = std::string(M350_MACHINES_DIR) + "/fanuc-0i";
    ProcessResult r = sim({"run", "count.nc", "--config", fanuc, "--dprnt", "out.txt", "--dprnt-limit", "2K"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    std::ifstream in(dir_ / "out.txt");
    std::stringstream text;
    text << in.rdbuf();
    const std::vector<std::string> kept = lines(text.str());
    ASSERT_GT(kept.size(), 10u) << text.str();
    EXPECT_LE(text.str().size(), 2048u + 200u) << text.str();
    EXPECT_EQ(kept.front(), "RECORD     1");
    EXPECT_EQ(kept.back(), "RECORD   500");
    int notes = 0;
    for (const std::string& line : kept) {
        notes += line.find("omitted: the output reached its limit") != std::string::npos ? 1 : 0;
    }
    EXPECT_EQ(notes, 1) << text.str();

    ProcessResult whole = sim({"run", "count.nc", "--config", fanuc, "--dprnt", "all.txt"});
    ASSERT_EQ(whole.exitStatus, kExitOk) << whole.err;
    std::ifstream all(dir_ / "all.txt");
    std::stringstream allText;
    allText << all.rdbuf();
    EXPECT_EQ(lines(allText.str()).size(), 500u) << "the default limit (64M) keeps all of it";
}

TEST_F(CliTest, ADprntLimitMustBeASizeInItsRange) {
    write("p.nc", "G0 X1\nM30\n");
    for (const char* bad : {"0", "-5", "lots", "5G", "1.5.2"}) {
        ProcessResult r = sim({"run", "p.nc", "--dprnt-limit", bad});
        EXPECT_EQ(r.exitStatus, kExitUsage) << bad << ": " << r.err;
        EXPECT_NE(r.err.find("--dprnt-limit"), std::string::npos) << bad << ": " << r.err;
    }
    ProcessResult outside = sim({"run", "p.nc", "--dprnt-limit", "5G"});
    EXPECT_NE(outside.err.find("the limit runs from 1 byte to 4G"), std::string::npos) << outside.err;
    for (const char* good : {"1", "64K", "4G"}) {
        ProcessResult r = sim({"run", "p.nc", "--dprnt-limit", good});
        EXPECT_EQ(r.exitStatus, kExitOk) << good << ": " << r.err;
    }
}

TEST_F(CliTest, DeeplyNestedLoopsAreCheckedQuicklyAndTheListIsCapped) {
    std::string text;
    for (int i = 0; i < 20000; ++i) {
        text += "WHILE [#1 LT 1] DO1\n";
    }
    write("nested.nc", text);
    ProcessResult r = sim({"check", "nested.nc", "--config", std::string(M350_MACHINES_DIR) + "/fanuc-0i"});
    EXPECT_NE(r.exitStatus, kExitOk);
    json j = output(r);
    const json& diagnostics = j["diagnostics"];
    ASSERT_EQ(diagnostics.size(), 1001u) << r.out.substr(0, 500);
    EXPECT_EQ(diagnostics[500].value("omitted", 0), 39999 - 1000);
    EXPECT_EQ(diagnostics[1000].value("line", 0), 20000);
}

} // namespace m350::clitest
