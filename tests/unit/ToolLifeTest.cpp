// FANUC 0i tool life management through the controller: G10 L3 data entry up to G11, T101 picking
// the group's first live tool, count life once per run at M06, minutes life in 4 s units of
// cutting feed only, a whole expired group going on with its last tool, H99/D99 (toollife.txt: ToolLifeFileTest.cpp).
#include "ToolLifeFixture.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(ToolLife, G10L3EntersGroupsAndToolsUpToG11) {
    ProgramRun run = runFanuc(lines({"G10 L3", "P1 L3 Q1", "T11 H11 D31", "T12 H12 D32", "P2 L1 Q2", "T21 H21",
                                     "G11", "M30"}));
    EXPECT_RUN_OK(run);
    const tools::LifeData& data = run.controller->toolLife().manager().data();
    ASSERT_EQ(data.groups.size(), 2u);
    EXPECT_EQ(data.groups[0].kind, tools::LifeKind::Count);
    EXPECT_EQ(data.groups[0].life, 3);
    ASSERT_EQ(data.groups[0].tools.size(), 2u);
    EXPECT_EQ(data.groups[0].tools[1].tool, 12);
    EXPECT_EQ(data.groups[0].tools[1].h, 12);
    EXPECT_EQ(data.groups[0].tools[1].d, 32);
    EXPECT_EQ(data.groups[1].kind, tools::LifeKind::Minutes);
    EXPECT_EQ(data.groups[1].tools[0].d, 0);
    EXPECT_TRUE(run.controller->toolLife().manager().changed());
    // the T words of the data selected nothing
    EXPECT_EQ(run.number(4120), 0);
}

TEST(ToolLife, G10L3ReplacesEverythingP1ChangesAGroupP2DeletesOne) {
    ProgramRun replaced = runProgram(fanucWithGroups(2), lines({"G10 L3", "P3 L5", "T31", "G11", "M30"}));
    EXPECT_RUN_OK(replaced);
    ASSERT_EQ(replaced.controller->toolLife().manager().data().groups.size(), 1u);
    EXPECT_EQ(replaced.controller->toolLife().manager().data().groups[0].number, 3);

    ProgramRun changed = runProgram(fanucWithGroups(2), lines({"G10 L3 P1", "P1 L4", "T13", "T11", "G11", "M30"}));
    EXPECT_RUN_OK(changed);
    ASSERT_EQ(changed.controller->toolLife().manager().data().groups.size(), 2u);
    EXPECT_EQ(used(changed, 1, 11), 2); // a changed group keeps what its tools used
    EXPECT_EQ(used(changed, 1, 13), 0);
    EXPECT_EQ(changed.controller->toolLife().manager().data().group(1)->life, 4);

    ProgramRun deleted = runProgram(fanucWithGroups(), lines({"G10 L3 P2", "P2", "G11", "M30"}));
    EXPECT_RUN_OK(deleted);
    EXPECT_EQ(deleted.controller->toolLife().manager().data().group(2), nullptr);
    EXPECT_NE(deleted.controller->toolLife().manager().data().group(1), nullptr);
}

TEST(ToolLife, BadDataBlocksAlarmAtTheirLine) {
    ProgramRun beyond = runFanuc(lines({"G10 L3", "P17 L3", "G11", "M30"}));
    ASSERT_EQ(beyond.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(beyond.report.alarm->line, 2u);
    EXPECT_NE(beyond.report.alarm->message.find("16 groups"), std::string::npos) << beyond.alarmText();

    ProgramRun motion = runFanuc(lines({"G10 L3", "P1 L3", "G1 X10", "G11", "M30"}));
    ASSERT_EQ(motion.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(motion.report.alarm->line, 3u);
    EXPECT_EQ(motion.controller->toolLife().manager().data().groups.size(), 0u); // nothing entered without G11

    ProgramRun noG10 = runFanuc(lines({"G11", "M30"}));
    ASSERT_EQ(noG10.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(noG10.report.alarm->message.find("G11 without G10 L3"), std::string::npos);

    // GS2 = 1: 32 groups of 8 tools (the 0i seed's table)
    config::MachineConfig gs1 = fanucMachine();
    gs1.toolLife.gs = 2;
    std::string nine = "G10 L3\nP20 L1\n";
    for (int t = 1; t <= 9; ++t) {
        nine += "T" + std::to_string(t) + "\n";
    }
    ProgramRun tooMany = runProgram(gs1, nine + "G11\nM30\n");
    ASSERT_EQ(tooMany.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(tooMany.report.alarm->line, 11u);
    EXPECT_NE(tooMany.report.alarm->message.find("at most 8 tools"), std::string::npos) << tooMany.alarmText();
}

TEST(ToolLife, T101SelectsTheGroupsFirstLiveToolAndOrdinaryTsStayTools) {
    ProgramRun run = runProgram(fanucWithGroups(3), lines({"T101 M06", "#100 = #4120", "T7", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 12); // T11 has used its 3 uses
    EXPECT_EQ(run.number(4120), 7);
    EXPECT_EQ(used(run, 1, 12), 1);

    ProgramRun unknown = runProgram(fanucWithGroups(), lines({"T105", "M30"}));
    ASSERT_EQ(unknown.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(unknown.report.alarm->message.find("group 5 is not entered"), std::string::npos);
}

TEST(ToolLife, CountLifeCountsOncePerRunAtTheToolChange) {
    ProgramRun run = runProgram(fanucWithGroups(1),
                                lines({"T101", "#100 = 0", "M06", "T101 M06", "T102 M06", "T101 M06", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 1, 11), 2); // once this run, however often group 1 is named
    EXPECT_EQ(used(run, 1, 12), 0);
    run.report = run.controller->run(); // the next run counts again
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 1, 11), 3);
    // T11's life (3) is over: the third run takes T12
    run.report = run.controller->run();
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(4120), 11 + 1);
    EXPECT_EQ(used(run, 1, 11), 3);
    EXPECT_EQ(used(run, 1, 12), 1);

    // selecting without M06 counts nothing
    ProgramRun noChange = runProgram(fanucWithGroups(), lines({"T101", "M30"}));
    EXPECT_EQ(used(noChange, 1, 11), 0);
}

TEST(ToolLife, AWholeExpiredGroupGoesOnWithItsLastToolAndRaisesTlch) {
    config::MachineConfig config = fanucWithGroups(3);
    config.toolLife.group(1)->tools[1].used = 3;
    ProgramRun run = runProgram(config, lines({"G0 X0", "T101 M06", "#100 = #1003", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(4120), 12);
    EXPECT_EQ(run.number(100), 1);
    EXPECT_TRUE(run.controller->toolLife().manager().toolChangeSignal());
    EXPECT_EQ(used(run, 1, 12), 4); // its uses go on being counted
    const std::vector<std::string>& messages = run.report.messages;
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages.front(),
              "tool life: every tool of group 1 has reached its life (T11 3/3, T12 3/3 uses): T12 goes on; tool change "
              "signal TLCH (#1003) = 1, replace the tools and reset the group");
}

TEST(ToolLife, MinutesLifeCountsCuttingFeedIn4SecondUnits) {
    // F600: 100 mm take 10 s, 20 mm 2 s; the rapids and the 30 s dwell do not count
    ProgramRun run = runProgram(fanucWithGroups(),
                                lines({"T102 M06", "G1 X100 F600", "G0 X0", "G4 X30", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 2, 21), 2); // 10 s: two whole units, 2 s not counted
    ProgramRun more = runProgram(fanucWithGroups(),
                                 lines({"T102 M06", "G1 X100 F600", "G0 X0", "G1 X20", "M30"}));
    EXPECT_EQ(used(more, 2, 21), 3); // 12 s
    // a new use starts from whole units: 3 s under the next M06 is not counted
    ProgramRun split = runProgram(fanucWithGroups(), lines({"T102 M06", "G1 X30 F600", "T102 M06", "G1 X0", "M30"}));
    EXPECT_EQ(used(split, 2, 21), 0);
}

TEST(ToolLife, AFeedHoldCountsNeitherTheWaitNorTheCutTwice) {
    ProgramRun run = loadProgram(fanucWithGroups(), lines({"T102 M06", "G1 X100 F600", "M30"}));
    ASSERT_TRUE(run.loaded);
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(5.0);
    c.hold(); // half way along the 10 s cut
    EXPECT_GT(c.displayPosition()(0), 10.0);
    EXPECT_LT(c.displayPosition()(0), 90.0);
    c.advance(60.0); // held for a minute: no cutting
    c.resume();
    while (c.advance(1.0) == controller::Controller::RunState::Running) {
    }
    EXPECT_EQ(c.runState(), controller::Controller::RunState::Finished);
    const tools::LifeTool& t21 = c.toolLife().manager().data().group(2)->tools[0];
    EXPECT_EQ(t21.used, 2); // 10 s of cutting in all: 5 s before the hold, 5 s after
}

TEST(ToolLife, AMinutesToolPastItsLifeIsSkippedNextTime) {
    config::MachineConfig config = fanucWithGroups();
    config.toolLife.group(2)->tools.push_back({22, 22, 42, 0});
    config.toolLife.group(2)->tools[0].used = 14; // one unit short of 1 minute
    ProgramRun run = runProgram(config, lines({"T102 M06", "G1 X100 F600", "T102", "#100 = #4120", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 2, 21), 16);
    EXPECT_EQ(run.number(100), 22);
}

TEST(ToolLife, H99AndD99TakeTheToolInUsesOffsets) {
    ProgramRun run = runProgram(fanucWithGroups(3), lines({"T101 M06", "G43 H99 Z0", "D99", "#100 = #4111",
                                                           "#101 = #4107", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 12);
    EXPECT_EQ(run.number(101), 32);

    ProgramRun none = runProgram(fanucWithGroups(), lines({"G43 H99 Z0", "M30"}));
    ASSERT_EQ(none.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(none.report.alarm->message.find("H99: no tool of a tool life group is in use"), std::string::npos);
}

TEST(ToolLife, OnTheM350TheTWordItselfChangesToTheGroupsTool) {
    config::MachineConfig config = bundledMachine();
    config.toolLife.putGroup(group(1, 5, tools::LifeKind::Count, {{3, 0, 0, 5}, {4, 0, 0, 0}}));
    ProgramRun run = runProgram(config, lines({"T101", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.controller->parameter(param::kCurrentTool), 4);
    EXPECT_EQ(used(run, 1, 4), 1);
}

TEST(ToolLife, AChangeThatNeverCompletesNeitherCountsNorPutsTheToolInUse) {
    // The tool-released sensor (IN11) never reports: the sensor watchdog stops O20000 waiting in
    // M301; T4 never reached the spindle, so its use is not counted and it is not in use.
    config::MachineConfig config = bundledMachine();
    config.toolLife.putGroup(group(1, 5, tools::LifeKind::Count, {{3, 0, 0, 5}, {4, 0, 0, 0}}));
    controller::RunSettings settings;
    settings.heldInputs[11] = 0;
    ProgramRun refused = runProgram(config, lines({"T101", "M30"}), settings);
    ASSERT_EQ(refused.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(refused.report.alarm->code, AlarmCode::SensorTimeout);
    EXPECT_EQ(used(refused, 1, 4), 0);
    EXPECT_FALSE(refused.controller->toolLife().manager().inUse().has_value());
    EXPECT_TRUE(refused.controller->toolLife().manager().selected().has_value()); // T4 stays selected for a retry

    settings.heldInputs.clear(); // the sensor repaired: the same change counts once
    ProgramRun retried = runProgram(config, lines({"T101", "M30"}), settings);
    EXPECT_RUN_OK(retried);
    EXPECT_EQ(used(retried, 1, 4), 1);
}

} // namespace
