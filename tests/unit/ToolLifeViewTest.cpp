// The tool life view the panel and m350-sim show (remaining life, the tool in use, expired and
// waiting sisters) and the operator's reset of a group's used life through the controller.
#include "core/tools/ToolLifeView.h"

#include "ToolLifeFixture.h"

#include <gtest/gtest.h>

namespace {

using namespace m350;
using namespace m350::test;

TEST(ToolLifeView, ShowsTheSisterInUseTheExpiredOneAndWhatIsLeft) {
    // T11 has 3 of 3 uses: T101 takes its sister T12, which this run counts once
    ProgramRun run = runProgram(fanucWithGroups(3), lines({"T101 M06", "T102", "M30"}));
    EXPECT_RUN_OK(run);
    tools::LifeView view = tools::makeLifeView(run.controller->toolLife().manager());
    EXPECT_EQ(view.ignoreNumber, 100);
    EXPECT_EQ(view.capacity.groups, 16);
    ASSERT_TRUE(view.inUse);
    EXPECT_EQ(view.inUse->group, 1);
    EXPECT_EQ(view.inUse->tool, 12);
    ASSERT_EQ(view.groups.size(), 2u);
    const tools::LifeGroupView& g1 = view.groups[0];
    EXPECT_EQ(g1.kind, tools::LifeKind::Count);
    EXPECT_EQ(g1.lifeUnits, 3);
    EXPECT_FALSE(g1.allExpired);
    ASSERT_EQ(g1.tools.size(), 2u);
    EXPECT_TRUE(g1.tools[0].expired);
    EXPECT_FALSE(g1.tools[0].inUse);
    EXPECT_EQ(g1.tools[0].remaining, 0);
    EXPECT_TRUE(g1.tools[1].inUse);
    EXPECT_FALSE(g1.tools[1].expired);
    EXPECT_EQ(g1.tools[1].used, 1);
    EXPECT_EQ(g1.tools[1].remaining, 2);
    // T102 selected group 2's T21; no M06 followed
    const tools::LifeGroupView& g2 = view.groups[1];
    EXPECT_EQ(g2.lifeUnits, 15);
    EXPECT_TRUE(g2.tools[0].selected);
    EXPECT_FALSE(g2.tools[0].inUse);
    EXPECT_EQ(g2.tools[0].remaining, 15);
}

TEST(ToolLifeView, WritesMinutesAsMinutesAndSeconds) {
    EXPECT_EQ(tools::lifeAmountText(tools::LifeKind::Count, 23), "23");
    EXPECT_EQ(tools::lifeAmountText(tools::LifeKind::Minutes, 23), "1:32");
    EXPECT_EQ(tools::lifeAmountText(tools::LifeKind::Minutes, 15), "1:00");
    EXPECT_EQ(tools::lifeAmountText(tools::LifeKind::Minutes, 2), "0:08");
}

TEST(ToolLifeView, TheOperatorResetsAGroupWhenNoProgramRuns) {
    ProgramRun run = loadProgram(fanucWithGroups(3), lines({"T101 M06", "G4 X10", "M30"}));
    ASSERT_TRUE(run.loaded);
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    Message why;
    EXPECT_FALSE(c.toolLife().resetGroup(1, &why));
    EXPECT_EQ(why, "a program runs: reset the tool life of group 1 when it has stopped");
    while (c.advance(1.0) == controller::Controller::RunState::Running) {
    }
    const std::uint64_t before = c.toolLife().manager().revision();
    c.toolLife().manager().markSaved();
    ASSERT_TRUE(c.toolLife().resetGroup(1, &why)) << why;
    EXPECT_TRUE(c.toolLife().manager().changed());
    EXPECT_GT(c.toolLife().manager().revision(), before);
    EXPECT_EQ(c.toolLife().manager().data().group(1)->tools[0].used, 0);
    EXPECT_EQ(c.toolLife().manager().data().group(1)->tools[1].used, 0);
    EXPECT_FALSE(c.toolLife().resetGroup(7, &why));
    EXPECT_EQ(why, "tool life group 7 is not entered");
    EXPECT_EQ(why.in(MessageLanguage::Chinese), "刀具寿命组7未输入"); // the panel's Tool Life page says it so
    // the next run starts again from T11
    ASSERT_TRUE(c.start());
    while (c.advance(1.0) == controller::Controller::RunState::Running) {
    }
    EXPECT_EQ(c.toolLife().manager().inUse()->tool, 11);
    EXPECT_EQ(c.toolLife().manager().data().group(1)->tools[0].used, 1);
}

} // namespace
