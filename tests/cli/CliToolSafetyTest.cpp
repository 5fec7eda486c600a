// Issue 25, what must never happen, through m350-sim: a rapid into the tool setter is a crash at
// its macro line; a stop inside a tool change leaves the tool unsure until the operator enters it
// (--estop-at, --confirm-tool); a tool that turns with no Z offset is warned of, once; setting a
// virtual tool again keeps its stored length.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace m350::clitest {

namespace {

std::string machine(const std::string& name) {
    return std::string(M350_MACHINES_DIR) + "/" + name;
}

class CliToolSafetyTest : public CliTest {
  protected:
    json run(const std::vector<std::string>& args, int exitStatus, ProcessResult* result = nullptr) {
        ProcessResult r = sim(args);
        EXPECT_EQ(r.exitStatus, exitStatus) << r.err << r.out;
        json j = output(r);
        json contract = j;
        contract.erase("spindle_load"); // fanuc-ts27r's load monitor
        expectRunContract(contract);
        if (result) {
            *result = r;
        }
        return j;
    }
};

} // namespace

// m350-linear16's setter top is -120: T2 (71.88 mm) trips at machine Z -48.12, so param 137 at
// T1's trip height (-53.677, the manual's number) sends T2's rapid 5.557 mm into the setter.
TEST_F(CliToolSafetyTest, O502RapidsALongerToolIntoTheSetterAndCrashesAtItsLine) {
    ProcessResult r;
    json j = run({"mdi", "M98P502", "--var", "1502=2", "--config", machine("m350-linear16"), "--tool", "2",
                  "--param", "137=-53.677", "--print", "1431"},
                 kExitAlarm, &r);
    EXPECT_EQ(j["alarm"]["code"], "crash");
    EXPECT_EQ(j["alarm"]["file"], "slib-probe.nc");
    EXPECT_EQ(j["alarm"]["line"], 50); // G53 Z#637: down to where probing starts
    EXPECT_NE(j["alarm"]["message"].get<std::string>().find("G00 drove T2 5.557 mm into the tool setter"),
              std::string::npos)
        << j["alarm"];
    EXPECT_EQ(j["vars"]["1431"], -48.12) << "T2's stored offset is left alone";
    EXPECT_NE(r.err.find("slib-probe.nc:50:"), std::string::npos) << r.err;
}

TEST_F(CliToolSafetyTest, O502WithProbingStartAboveTheToolSetsItWithoutACrash) {
    json j = run({"mdi", "M98P502", "--var", "1502=2", "--config", machine("m350-linear16"), "--tool", "2",
                  "--param", "931=0", "--print", "1431"},
                 kExitOk);
    EXPECT_NEAR(j["vars"]["1431"].get<double>(), -48.12, 1e-6);
}

// fanuc-ts27r: G65 P9858 T2 expects T2 (95.5 mm) and rapids to 10 mm above the stylus for it;
// with T1 (120 mm) in the spindle the tip goes 14.5 mm through the stylus.
TEST_F(CliToolSafetyTest, O9858WithTheWrongToolCrashesIntoTheStylusAtItsRapid) {
    ProcessResult r;
    json j =
        run({"mdi", "G91 G28 Z0", "G65 P9858 T2 H0.5", "--config", machine("fanuc-ts27r"), "--tool", "1"},
            kExitAlarm, &r);
    EXPECT_EQ(j["alarm"]["code"], "crash");
    EXPECT_EQ(j["alarm"]["file"], "breakage.nc");
    EXPECT_EQ(j["alarm"]["line"], 94); // G00 Z[#31 - #16]
    EXPECT_NE(j["alarm"]["message"].get<std::string>().find("G00 drove T1 14.500 mm into the tool setter"),
              std::string::npos)
        << j["alarm"];
    EXPECT_NE(r.err.find("breakage.nc:94:"), std::string::npos) << r.err;
}

TEST_F(CliToolSafetyTest, AnEStopInsideT2LeavesTheToolUnsureAndConfirmToolSettlesIt) {
    const std::vector<std::string> stop{"mdi",        "T2", "--config", machine("m350-linear16"),
                                        "--estop-at", "10",  "--print",  "1300"};
    json stopped = run(stop, kExitAlarm);
    EXPECT_EQ(stopped["alarm"]["code"], "emergency_stop");
    ASSERT_TRUE(stopped.contains("tool_unsure")) << stopped;
    EXPECT_EQ(stopped["tool_unsure"]["message_id"], "tool_unsure");
    EXPECT_EQ(stopped["tool_unsure"]["arguments"], json::array({"2", "1"}));
    EXPECT_EQ(stopped["vars"]["1300"], 1);
    EXPECT_NE(stopped["tool"], 1)
        << "the stop came after T1 left the spindle: #1300 and the spindle disagree";

    std::vector<std::string> confirm = stop;
    confirm.insert(confirm.end(), {"--confirm-tool", std::to_string(stopped["tool"].get<int>())});
    json settled = run(confirm, kExitOk);
    EXPECT_FALSE(settled.contains("tool_unsure")) << settled;
    EXPECT_EQ(settled["vars"]["1300"], settled["tool"]);
    EXPECT_EQ(settled["tool"], stopped["tool"]);
}

TEST_F(CliToolSafetyTest, AToolTurningWithNoZOffsetIsWarnedOfOnce) {
    json j = run({"mdi", "T5", "M3 S1000", "G91 G1 X10 F500", "M5", "M3 S2000", "G1 X10", "M5", "T4",
                  "M3 S1000", "M5", "--config", machine("m350-linear16")},
                 kExitOk);
    ASSERT_TRUE(j.contains("warnings")) << j;
    ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
    EXPECT_EQ(j["warnings"][0]["message_id"], "tool_length_unset");
    EXPECT_EQ(j["warnings"][0]["arguments"], json::array({"5", "934"}));
    const std::string said = j["warnings"][0]["message"];
    const auto& messages = j["messages"];
    EXPECT_EQ(std::count(messages.begin(), messages.end(), said), 1) << messages;
}

// T17 is a virtual tool (param 803): the operator puts it in by hand. Setting it again on the fixed
// setter measures what it is, and what was stored for it is what it is.
TEST_F(CliToolSafetyTest, SettingAVirtualToolAgainKeepsItsStoredLength) {
    json j = run({"mdi", "M98P505", "--var", "1970=17", "--config", machine("m350-linear16"), "--param",
                  "973=-50.5", "--print", "1473,1300"},
                 kExitOk);
    EXPECT_EQ(j["vars"]["1300"], 17);
    EXPECT_NEAR(j["vars"]["1473"].get<double>(), -50.5, 1e-6);
}

} // namespace m350::clitest
