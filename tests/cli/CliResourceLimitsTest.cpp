// Issue 13: running out of memory ends in an exit status and a JSON error, never an abort.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <sstream>

namespace m350::clitest {

TEST_F(CliTest, RunningOutOfMemoryIsAJsonErrorNotAnAbort) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: a 60 MB limit stops it at start";
#else
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
#endif
}

} // namespace m350::clitest
