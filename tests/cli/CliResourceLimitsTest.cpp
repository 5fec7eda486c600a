// Issue 13: running out of memory ends in an exit status and a JSON error, never an abort.
#include "tests/cli/CliFixture.h"
#include "tests/support/Sanitized.h"

#include <gtest/gtest.h>

#include <sstream>

namespace m350::clitest {

TEST_F(CliTest, RunningOutOfMemoryIsAJsonErrorNotAnAbort) {
    if (test::kSanitized) {
        GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: a 60 MB limit stops it at start";
    }
    std::ostringstream program; // 400,000 lines, 13 MB: its parsed form needs about 100 MB
    for (int i = 0; i < 400000; ++i) {
        program << "G1 X" << i % 100 << ".123 Y" << (i * 7) % 100 << ".456 Z-" << i % 10 << ".789 F1000\n";
    }
    program << "M30\n";
    write("big.nc", program.str());
    ProcessResult r = m350::testing::runProcess(
        "/bin/sh", {"-c", std::string("ulimit -v 60000; exec '") + M350_SIM_PATH + "' check big.nc"}, dir_.string());
    EXPECT_EQ(r.exitStatus, kExitError) << r.err;
    EXPECT_NE(r.err.find("m350-sim: out of memory"), std::string::npos) << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "error") << r.out;
    EXPECT_EQ(j["alarm"].value("code", ""), "out_of_memory") << r.out;

    ProcessResult roomy = sim({"check", "big.nc"}); // the same program with the memory it needs
    EXPECT_EQ(roomy.exitStatus, kExitOk) << roomy.err;
}

// A program above 64 MiB is kept in memory only in part (the chunks that loops, jumps and macro
// statements need); the rest is parsed again from the mapped file as it runs. Kept whole, this
// 70 MB program would need about 400 MB; here it runs in 150 MB of address space, the mapped file
// included.
TEST_F(CliTest, AProgramAbove64MiBRunsInBoundedMemory) {
    if (test::kSanitized) {
        GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: an address-space limit stops it at start";
    }
    std::string program;
    constexpr int kLines = 2'300'000;
    program.reserve(std::size_t{kLines} * 32);
    program += "#1 = 0\n";
    for (int i = 0; i < kLines; ++i) {
        program += "G1 X" + std::to_string(i % 100) + ".125 Y" + std::to_string((i * 7) % 100) + ".5 Z-" +
                   std::to_string(i % 10) + ".25 F1000\n";
    }
    program += "#1 = [#1 + 1] * 7\nG1 X12.5 Y-3.25 Z0\nM30\n";
    ASSERT_GT(program.size(), std::size_t{64} << 20);
    write("big.nc", program);
    ProcessResult r = m350::testing::runProcess(
        "/bin/sh",
        {"-c", std::string("ulimit -v 150000; exec '") + M350_SIM_PATH + "' run big.nc --max-sim-time 1e9 --print 1"},
        dir_.string());
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("status", ""), "ok") << r.out.substr(0, 2000);
    EXPECT_EQ(j["vars"].value("1", 0.0), 7.0) << r.out.substr(0, 2000);
    EXPECT_EQ(j["work"].value("X", 0.0), 12.5) << r.out.substr(0, 2000);
    EXPECT_EQ(j["work"].value("Y", 0.0), -3.25) << r.out.substr(0, 2000);
}

} // namespace m350::clitest
