// The bundled magazines through m350-sim, as an engineer scripting checks of a machine folder
// would drive them: --config, --tool, --input, and what the report says of the tools.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

std::string machine(const std::string& name) {
    return std::string(M350_MACHINES_DIR) + "/" + name;
}

TEST_F(CliTest, UmbrellaM06ExchangesThroughThePapersO9001) {
    ProcessResult r = sim({"mdi", "G90", "M06 T5", "--config", machine("fanuc-umbrella"), "--tool", "3", "--print",
                           "1000,4003"});
    ASSERT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j.value("tool", -1), 5);
    EXPECT_EQ(j["pockets"].value("3", -1), 3);
    EXPECT_EQ(j["pockets"].value("5", -1), 0);
    EXPECT_EQ(j["vars"].value("1000", json()), 1);
    EXPECT_EQ(j["vars"].value("4003", json()), 90);
}

TEST_F(CliTest, ServoDiscWithItsInPositionSensorHeldOffStopsNamingIt) {
    ProcessResult r = sim({"mdi", "T3", "--config", machine("m350-servo-disc"), "--input", "IN13=0",
                           "--sensor-timeout", "1.5"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("code", std::string()), "sensor_timeout");
    EXPECT_NE(j["alarm"].value("message", std::string()).find("IN13 (disc in position) never became 1: waited 1.5 s"),
              std::string::npos)
        << j["alarm"];
    EXPECT_NE(r.err.find("slib-g.nc:"), std::string::npos) << r.err;
}

TEST_F(CliTest, MultiHeadAndManualMachinesChangeTools) {
    json heads = output(sim({"mdi", "T4", "--config", machine("m350-multi-head")}));
    EXPECT_EQ(heads.value("tool", -1), 4);
    EXPECT_EQ(heads["outputs"][5], 1); // OUT06: head 4's cylinder
    json manual = output(sim({"mdi", "T2", "--config", machine("m350-manual")}));
    EXPECT_EQ(manual.value("tool", -1), 2);
    EXPECT_EQ(manual.value("status", std::string()), "ok");
}

// A tool the spindle lets go of away from the rack lies on the table: the report lists it under
// fallen_tools with where it fell, so a census of tool, pockets and fallen_tools finds every tool once.
TEST_F(CliTest, AToolReleasedAwayFromTheRackIsReportedOnTheTable) {
    ProcessResult r = sim({"mdi", "G53 G0 X300 Y200", "M154", "--config", machine("m350-linear16"), "--tool", "3"});
    json j = output(r);
    EXPECT_EQ(j.value("tool", -1), 0) << r.err;
    ASSERT_TRUE(j.contains("fallen_tools")) << j;
    ASSERT_EQ(j["fallen_tools"].size(), 1u) << j;
    const json& fallen = j["fallen_tools"][0];
    EXPECT_EQ(fallen.value("tool", 0), 3);
    EXPECT_DOUBLE_EQ(fallen["at"].value("X", 0.0), 300.0);
    EXPECT_DOUBLE_EQ(fallen["at"].value("Y", 0.0), 200.0);
    std::map<int, int> places;
    for (const auto& [pocket, tool] : j["pockets"].items()) {
        ++places[tool.get<int>()];
    }
    places.erase(0);
    ++places[fallen.value("tool", 0)];
    for (int tool = 1; tool <= 16; ++tool) {
        EXPECT_EQ(places[tool], 1) << "T" << tool << ": " << j;
    }
    EXPECT_NE(r.err.find("T3 lies on the table: it fell where the spindle released it at X300.000 Y200.000"),
              std::string::npos)
        << r.err;

    json kept = output(sim({"mdi", "G53 G0 X300 Y200", "--config", machine("m350-linear16"), "--tool", "3"}));
    EXPECT_FALSE(kept.contains("fallen_tools")) << "the key appears only when a tool fell";
}

} // namespace m350::clitest

namespace m350::clitest {

// The alarm by message id: the JSON keeps its English message and code and gives the id and the
// arguments; --lang zh_CN says the alarm line (and the tool left on the table) in Chinese.
TEST_F(CliTest, ACrashAlarmHasItsMessageIdAndIsSaidInChineseWithLangZhCn) {
    write("drop.nc", "G53 G00 X300 Y200 Z-10\nM154\nM30\n");
    ProcessResult english = sim({"run", "drop.nc", "--tool", "1"});
    ProcessResult chinese = sim({"run", "drop.nc", "--tool", "1", "--lang", "zh_CN"});
    for (const ProcessResult* r : {&english, &chinese}) {
        EXPECT_EQ(r->exitStatus, kExitAlarm) << r->err;
        json j = output(*r);
        EXPECT_EQ(j["alarm"].value("code", ""), "crash");
        EXPECT_EQ(j["alarm"].value("message_id", ""), "rack_dropped");
        EXPECT_EQ(j["alarm"]["message_arguments"], (json{"1", "X300.000 Y200.000 Z-10.000"}));
        EXPECT_EQ(j["alarm"].value("message", ""), "T1 dropped: the drawbar was released at X300.000 Y200.000 "
                                                   "Z-10.000 with no pocket under the tool (it fell onto the table)");
    }
    EXPECT_NE(english.err.find("alarm: T1 dropped: the drawbar was released"), std::string::npos) << english.err;
    EXPECT_NE(chinese.err.find("报警: T1掉落：在X300.000 Y200.000 Z-10.000松刀时刀具下方没有刀位"), std::string::npos)
        << chinese.err;
    EXPECT_NE(chinese.err.find("m350-sim: T1掉在工作台上"), std::string::npos) << chinese.err;
    EXPECT_EQ(chinese.err.find("dropped"), std::string::npos) << chinese.err;
    ProcessResult bad = sim({"run", "drop.nc", "--lang", "fr"});
    EXPECT_EQ(bad.exitStatus, 64) << bad.err;
}

} // namespace m350::clitest
