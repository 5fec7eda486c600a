// Which axes a machine has, from its parameters: the drive assignment (488-492), the axis-follow
// function (22, 24), the 4th/5th names (443/444) and types (449/450).
#include "core/params/AxisSetup.h"
#include "core/params/ParameterTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <utility>

using m350::params::AxisSetup;
using m350::params::axisSetup;
using m350::params::ParameterTable;

namespace {

ParameterTable withParameters(std::initializer_list<std::pair<int, double>> values) {
    ParameterTable table;
    for (auto [number, value] : values) {
        table.set(number, value);
    }
    return table;
}

// Params 488-492: the programming axis drives 1-5 obey.
ParameterTable withDrives(double d1, double d2, double d3, double d4, double d5) {
    return withParameters({{488, d1}, {489, d2}, {490, d3}, {491, d4}, {492, d5}});
}

} // namespace

TEST(AxisSetup, AFolderThatSetsNoDrivesHasXYZ) {
    AxisSetup axes = axisSetup(ParameterTable{});
    EXPECT_EQ(axes.count, 3);
    EXPECT_TRUE(axes.present(2));
    EXPECT_FALSE(axes.present(3));
    EXPECT_FALSE(axes.present(4));
    EXPECT_EQ(axes.names[3], 'A') << "an unset 443 (0) does not call the 4th axis X";
    EXPECT_EQ(axes.names[4], 'B');
}

TEST(AxisSetup, TheOwnersGantryHasAAndARotaryB) {
    // drive 4 obeys Y (the gantry's second motor), drive 5 the 5th axis, named B and rotary
    ParameterTable p = withDrives(0, 1, 2, 1, 4);
    p.set(443, 3);
    p.set(444, 4);
    p.set(450, 1);
    AxisSetup axes = axisSetup(p);
    EXPECT_EQ(axes.count, 5);
    EXPECT_EQ(axes.names[3], 'A');
    EXPECT_FALSE(axes.rotary[3]);
    EXPECT_EQ(axes.names[4], 'B');
    EXPECT_TRUE(axes.rotary[4]);
}

TEST(AxisSetup, ADualYGantryAloneHasAnA) {
    EXPECT_EQ(axisSetup(withDrives(0, 1, 2, 1, 0)).count, 4);
}

TEST(AxisSetup, ARotaryFourthOnItsOwnDrive) {
    ParameterTable p = withDrives(0, 1, 2, 3, 0);
    p.set(449, 1);
    AxisSetup axes = axisSetup(p);
    EXPECT_EQ(axes.count, 4);
    EXPECT_TRUE(axes.rotary[3]);
    EXPECT_FALSE(axes.present(4));
}

TEST(AxisSetup, TheFifthOnTheFourthDriveBringsTheFourthToo) {
    // #1995 is a count: axes 1..5 exist once the 5th does
    EXPECT_EQ(axisSetup(withDrives(0, 1, 2, 4, 0)).count, 5);
}

TEST(AxisSetup, TheFollowFunctionsFollowerIsAnAxis) {
    EXPECT_EQ(axisSetup(withParameters({{22, 1}, {23, 1}, {24, 3}})).count, 4);
    EXPECT_EQ(axisSetup(withParameters({{22, 0}, {23, 1}, {24, 3}})).count, 3) << "the function is off";
    EXPECT_EQ(axisSetup(withParameters({{22, 1}, {23, 2}, {24, 1}})).count, 3) << "Y following Z adds nothing";
}

TEST(AxisSetup, TheFourthIsNamedAsParam443Says) {
    ParameterTable p = withDrives(0, 1, 2, 3, 0);
    p.set(443, 5);
    EXPECT_EQ(axisSetup(p).names[3], 'C');
    p.set(443, 1); // Y: a second axis called Y would be two axes with one letter
    EXPECT_EQ(axisSetup(p).names[3], 'A');
}

TEST(AxisSetup, ValuesThatNameNoAxisAreIgnored) {
    for (double bad : {-1.0, 2.5, 5.0, 7.0, std::nan("")}) {
        EXPECT_EQ(axisSetup(withDrives(0, 1, 2, bad, 0)).count, 3) << bad;
    }
}
