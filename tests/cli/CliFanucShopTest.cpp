// FANUC shop programs as they run on the control, through m350-sim as a user runs them: a probing
// package's compact G65 calls, the system variables a 0i has for automatic operation and the PMC's
// interface signals, G and M codes that call macros by parameter, and the refusals programs for
// other controls (Haas, Brother) meet on the FANUC machines.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

namespace {

// The probing package's call as the shop wrote it: every argument from a variable, no spaces, the
// last one `E2.` right after `Y#32`.
const char* const kProbeCall = "%\nO1000(PROBE WEB)\n#7=6.#15=150.#11=1.#13=0.5\n#19=3.#20=12.#23=4.#31=25.#32=-18.5\n"
                               "G65P9730D#7F#15H#11M#13S#19T#20W#23X#31Y#32E2.\nM30\n"
                               "O9730\n#100=#24\n#101=#25\n#102=#8\n#103=#7+#9+#11+#13+#19+#20+#23\nM99\n%\n";

} // namespace

TEST_F(CliTest, AVariableFollowedByEIsTwoWordsInAProbingCall) {
    write("probe.nc", kProbeCall);
    ProcessResult check = sim({"check", "probe.nc", "--dialect", "fanuc"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    EXPECT_EQ(output(check).value("status", ""), "ok") << check.out;
    ProcessResult r = sim({"run", "probe.nc", "--dialect", "fanuc", "--print", "100,101,102,103"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"], json({{"100", 25.0}, {"101", -18.5}, {"102", 2.0}, {"103", 176.5}})) << r.out;
}

TEST_F(CliTest, AVariableFollowedByEIsTwoWordsOnTheM350Too) {
    write("move.nc", "#31=1.#32=2.\nG90G1X#31Y#32E2.F100\nM30\n");
    ProcessResult check = sim({"check", "move.nc"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult r = sim({"run", "move.nc"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_DOUBLE_EQ(j["work"].value("X", 0.0), 1.0) << r.out;
    EXPECT_DOUBLE_EQ(j["work"].value("Y", 0.0), 2.0) << r.out;
}

TEST_F(CliTest, ExponentNotationStaysRefusedAtItsLineAndColumn) {
    for (const char* dialect : {"m350", "fanuc"}) {
        write("exp.nc", "#1=2.\nG1X#1Y1.E2\nM30\n");
        ProcessResult r = sim({"check", "exp.nc", "--dialect", dialect});
        EXPECT_EQ(r.exitStatus, kExitError) << dialect;
        EXPECT_NE(r.err.find("exp.nc:2:7: '1.E2' is not a G-code number"), std::string::npos) << dialect << r.err;
    }
}

} // namespace m350::clitest
