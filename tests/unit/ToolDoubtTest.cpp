// Issue 25: an E-stop or RESET inside a tool change leaves the controller unsure which tool the
// spindle holds. It says so (the firmware's msg 867 family), refuses the next change at its word
// until the operator enters the tool, and then #1300, the panel and the report agree.
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using controller::Controller;

// Runs `change` and stops it (E-stop, or RESET when `estop` is false) a second after the spindle
// let go of the old tool: it is back in its pocket and the new one not yet fetched. (At the moment
// the drawbar lets go the stop would clamp it on the old tool again.)
void stopWithEmptySpindle(Controller& c, const std::string& change, bool estop) {
    ASSERT_TRUE(c.loadMdi({change}));
    ASSERT_TRUE(c.start());
    for (int step = 0; step < 2000 && c.status().report().tool != 0; ++step) {
        ASSERT_EQ(c.advance(0.02), Controller::RunState::Running);
    }
    ASSERT_EQ(c.status().report().tool, 0) << "the change never emptied the spindle";
    ASSERT_EQ(c.advance(1.0), Controller::RunState::Running);
    ASSERT_EQ(c.status().report().tool, 0) << "the new tool came within a second";
    estop ? c.emergencyStop() : c.reset();
}

int recordedTool(Controller& c) {
    return static_cast<int>(c.variable(1300).number);
}

TEST(ToolDoubt, AnEStopInT2LeavesTheToolUnsureAndT3IsRefusedUntilTheOperatorEntersIt) {
    Controller c(test::bundledMachine("m350-linear16"), {});
    ASSERT_EQ(c.status().report().tool, 1);
    stopWithEmptySpindle(c, "T2", true);
    ASSERT_EQ(c.status().report().tool, 0);

    // what the controller recorded and what the spindle holds differ, and it says so
    EXPECT_EQ(recordedTool(c), 1);
    controller::RunReport stopped = c.status().report();
    ASSERT_TRUE(stopped.toolUnsure);
    EXPECT_EQ(stopped.toolUnsure->messageId, "tool_unsure");
    EXPECT_EQ(stopped.toolUnsure->messageArguments, (std::vector<std::string>{"2", "1"}));
    EXPECT_NE(stopped.toolUnsure->message.find("[T2]"), std::string::npos) << stopped.toolUnsure->message;
    ASSERT_TRUE(c.panelStatus().toolUnsure);
    const std::vector<std::string> said = stopped.messages;
    EXPECT_EQ(std::count(said.begin(), said.end(), stopped.toolUnsure->message), 1);

    // RESET clears the E-stop's alarm, not the doubt (and says nothing twice)
    c.reset();
    ASSERT_FALSE(c.status().report().alarm);
    ASSERT_TRUE(c.toolDoubt().doubt());
    ASSERT_TRUE(c.loadMdi({"M5", "T3"}));
    controller::RunReport refused = c.run();
    ASSERT_EQ(refused.status, controller::RunStatus::Alarm);
    ASSERT_TRUE(refused.alarm);
    EXPECT_EQ(refused.alarm->messageId, "tool_unsure_refused");
    EXPECT_EQ(refused.alarm->message,
              "No tool change before the operator enters the tool the spindle holds: a change to T2 was stopped");
    EXPECT_EQ(messageText(refused.alarm->messageId, refused.alarm->messageArguments, MessageLanguage::Chinese),
              "换刀T2被中断: 输入主轴上的刀号之前不能换刀!");
    EXPECT_EQ(refused.alarm->line, 2u);
    EXPECT_EQ(refused.alarm->column, 1u);
    EXPECT_EQ(refused.tool, 0) << "nothing moved towards a pocket";
    EXPECT_EQ(std::count(refused.messages.begin(), refused.messages.end(), stopped.toolUnsure->message), 1);

    // the operator finds the spindle empty and says so: #1300, the panel and the report agree
    c.reset();
    ASSERT_TRUE(c.setSpindleToolNumber(0));
    EXPECT_FALSE(c.toolDoubt().doubt());
    EXPECT_FALSE(c.status().report().toolUnsure);
    EXPECT_FALSE(c.panelStatus().toolUnsure);
    EXPECT_EQ(recordedTool(c), 0);
    EXPECT_EQ(c.panelStatus().tool, 0);
    EXPECT_EQ(c.status().report().tool, 0);
}

TEST(ToolDoubt, AfterTheOperatorEntersTheToolTheNextChangeRunsAndEveryViewAgrees) {
    Controller c(test::bundledMachine("m350-servo-disc"), {});
    const int before = c.status().report().tool;
    ASSERT_NE(before, 0);
    stopWithEmptySpindle(c, before == 2 ? "T3" : "T2", false);
    ASSERT_TRUE(c.toolDoubt().doubt());
    ASSERT_TRUE(c.setSpindleToolNumber(c.status().report().tool));
    ASSERT_TRUE(c.loadMdi({"T4"}));
    controller::RunReport done = c.run();
    ASSERT_EQ(done.status, controller::RunStatus::Ok) << (done.alarm ? done.alarm->message : "");
    EXPECT_EQ(done.tool, 4);
    EXPECT_EQ(recordedTool(c), 4);
    EXPECT_EQ(c.panelStatus().tool, 4);
    EXPECT_FALSE(done.toolUnsure);
}

TEST(ToolDoubt, AFanucChangeStoppedRefusesTheNextM06AtItsWord) {
    controller::RunSettings settings;
    settings.tool = 1;
    Controller c(test::bundledMachine("fanuc-umbrella"), settings);
    stopWithEmptySpindle(c, "M06 T2", true);
    controller::RunReport stopped = c.status().report();
    ASSERT_TRUE(stopped.toolUnsure);
    EXPECT_EQ(stopped.toolUnsure->messageArguments.front(), "2");
    c.reset();
    ASSERT_TRUE(c.loadMdi({"T3 M06"}));
    controller::RunReport refused = c.run();
    ASSERT_TRUE(refused.alarm);
    EXPECT_EQ(refused.alarm->messageId, "tool_unsure_refused");
    EXPECT_EQ(refused.alarm->column, 4u);
}

TEST(ToolDoubt, AStopOutsideAChangeAndAChangeRunToItsEndLeaveNoDoubt) {
    Controller c(test::bundledMachine("m350-linear16"), {});
    ASSERT_TRUE(c.loadMdi({"T2"}));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    ASSERT_TRUE(c.loadMdi({"G91 G1 X100 F100"}));
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    c.emergencyStop();
    c.reset();
    EXPECT_FALSE(c.toolDoubt().doubt());
    EXPECT_FALSE(c.status().report().toolUnsure);
    EXPECT_EQ(recordedTool(c), 2);
    EXPECT_EQ(c.status().report().tool, 2);
}

} // namespace
