// The spindle's tool where no magazine device knows it: an M06 by hand names it, M61 sets it
// without moving a pocket, and only a random changer puts the old tool into the new one's pocket.
#include "core/controller/SpindleToolByHand.h"

#include "core/gcode/Dialect.h"
#include "core/params/ParameterTable.h"
#include "core/tools/ToolTableFile.h"

#include <gtest/gtest.h>

namespace m350::test {

namespace {

tools::ToolData pocketsOneTwoThree(params::ParameterTable& parameters) {
    return tools::ToolData(gcode::Dialect::fanuc(), parameters, tools::parseToolTable("T1 P1\nT2 P2\nT3 P3\n", "t").table);
}

} // namespace

TEST(SpindleToolByHand, ARandomChangerSwapsPocketsAtM06ButNotAtM61) {
    params::ParameterTable parameters;
    tools::ToolData tools = pocketsOneTwoThree(parameters);
    controller::SpindleToolByHand spindle(tools, true);
    spindle.set(1);
    spindle.take({2, false}); // M06 T2: T1 goes into T2's pocket
    EXPECT_EQ(spindle.tool(), 2);
    EXPECT_EQ(tools.find(1)->pocket, 2);
    EXPECT_EQ(tools.find(2)->pocket, 0);
    spindle.take({3, true}); // M61 Q3: the number alone
    EXPECT_EQ(spindle.tool(), 3);
    EXPECT_EQ(tools.find(2)->pocket, 0);
    EXPECT_EQ(tools.find(3)->pocket, 3);
}

TEST(SpindleToolByHand, AFixedPocketChangerMovesNoPocketAndM85SeesTheTool) {
    params::ParameterTable parameters;
    tools::ToolData tools = pocketsOneTwoThree(parameters);
    controller::SpindleToolByHand spindle(tools, false);
    spindle.take({2, false});
    EXPECT_EQ(spindle.tool(), 2);
    EXPECT_EQ(tools.find(1)->pocket, 1);
    EXPECT_EQ(tools.find(2)->pocket, 2);
    spindle.pmcRegister() = 3; // M85 writes the register
    EXPECT_EQ(spindle.tool(), 3);
}

} // namespace m350::test
