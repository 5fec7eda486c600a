// A block starts a call by its codes as evaluated: written plainly, through a variable, or a value
// a hair off the whole code (the executor passes plain blocks on the bits of their whole codes 0-127
// and asks every word of any other block).
#include "RunProgram.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(CallCodes, ACallCodeFromAVariableOrAHairOffTheWholeCodeStillCalls) {
    auto run = runM350(lines({"#1 = 98", "M#1 P100", "#2 = 98.00000000001", "M#2 P100", "G[65 - 0.00000000001] P100",
                              "G1 X1 F100", "M30", "O100", "#100 = #100 + 1", "M99"}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 3);
}

TEST(CallCodes, AFractionalCodeThatIsNoCallIsRefusedByTheInterpreter) {
    auto run = runM350(lines({"G1.5 X1 F100", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_NE(run.report.alarm->message.find("G1.5"), std::string::npos) << run.alarmText();
}

} // namespace
