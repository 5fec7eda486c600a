// The machine view's scene (core/preview/MachineScene.h) of the bundled machine folders, driven
// through the Controller as the panel drives it: pockets at their parameters with the tools they
// hold, a change moving a tool, carousels turning, setters, soft limits, offsets and tool lengths.
#include "core/preview/MachineScene.h"

#include "RunProgram.h"

#include <gtest/gtest.h>

#include <chrono>

namespace {

using namespace m350;
using namespace m350::test;
using preview::MachineScene;
using preview::SceneMagazine;
using preview::SceneSetter;

controller::RunReport mdi(controller::Controller& c, std::initializer_list<std::string> lines) {
    EXPECT_TRUE(c.loadMdi(lines));
    controller::RunReport r = c.run();
    return r;
}

#define ASSERT_RAN(r) ASSERT_EQ((r).status, controller::RunStatus::Ok) << ((r).alarm ? (r).alarm->message : "")

const preview::SceneLevel* levelOf(const MachineScene& s, const std::string& id) {
    for (const preview::SceneLevel& level : s.levels) {
        if (level.label.id == id) {
            return &level;
        }
    }
    return nullptr;
}

double distanceXY(const preview::ScenePoint& a, const preview::ScenePoint& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

TEST(MachineScene, LinearRackPocketsStandAtTheirParametersAndAChangeMovesTheTool) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::LinearRack);
    EXPECT_FALSE(s.magazine.topLoading);
    EXPECT_EQ(s.magazine.openingY, 1.0);
    ASSERT_EQ(s.magazine.pockets.size(), 16u); // param 801, each pocket's 830+/850+/870+ set
    const preview::ScenePocket& third = s.magazine.pockets[2];
    EXPECT_EQ(third.number, 3);
    EXPECT_EQ(third.at, (preview::ScenePoint{170.0, 5.0, -80.0})); // params 832, 852, 872
    EXPECT_EQ(third.tool, 3);
    EXPECT_EQ(s.magazine.pockets[0].tool, 0); // T1 is in the spindle (param 800)
    EXPECT_EQ(s.spindleTool, 1);

    ASSERT_RAN(mdi(c, {"T3"}));
    MachineScene after = preview::buildScene(c);
    EXPECT_EQ(after.spindleTool, 3);
    EXPECT_EQ(after.magazine.pockets[2].tool, 0);
    EXPECT_EQ(after.magazine.pockets[0].tool, 1);
    EXPECT_NE(after, s);
    EXPECT_EQ(preview::buildScene(c), after); // nothing changed: the same scene

    // the levels its O20000 uses: 806 up, 807 down, the pockets' Z
    ASSERT_TRUE(levelOf(after, "scene_level_change_up"));
    EXPECT_EQ(levelOf(after, "scene_level_change_up")->z, 0.0);
    ASSERT_TRUE(levelOf(after, "scene_level_change_down"));
    EXPECT_EQ(levelOf(after, "scene_level_change_down")->z, -80.0);
    const preview::SceneLevel* pockets = levelOf(after, "scene_level_pocket");
    ASSERT_TRUE(pockets);
    EXPECT_EQ(pockets->z, -80.0);
    EXPECT_EQ(pockets->label.english(), "pocket height T1-16");
    EXPECT_EQ(pockets->label.in(MessageLanguage::Chinese), "刀位高度 T1-16");
}

TEST(MachineScene, ToolLengthsComeFromTheZOffsetsElseTheWorld) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    ASSERT_TRUE(c.setParameter(932, -50.0)); // T3's Z offset: trips 70 mm above the setter's top (-120)
    ASSERT_RAN(mdi(c, {"T3"}));
    MachineScene s = preview::buildScene(c);
    ASSERT_TRUE(s.tool(3));
    EXPECT_NEAR(s.tool(3)->length, 70.0, 1e-9); // not the world's 58.695
    ASSERT_TRUE(s.tool(5));
    EXPECT_NEAR(s.tool(5)->length, 64.5, 1e-9); // param 934 is 0: machine.toml's [tools] length
    EXPECT_NEAR(s.tool(1)->length, 66.323, 1e-9); // param 930 -53.677 less the setter top -120
    EXPECT_EQ(s.tool(1)->diameter, 0.0); // no table D, no [tools] diameter
    EXPECT_FALSE(s.tool(17)); // in no pocket and not in the spindle: nothing draws it
}

TEST(MachineScene, AFanucsToolsComeFromTheOffsetMemory) {
    controller::RunSettings settings;
    settings.tool = 2;
    controller::Controller c(bundledMachine("fanuc-ts27r"), settings);
    ASSERT_RAN(mdi(c, {"G10 L10 P2 R100.0", "G10 L12 P2 R9.0"})); // memory C: H and D geometry of 2
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.spindleTool, 2);
    ASSERT_TRUE(s.tool(2));
    EXPECT_NEAR(s.tool(2)->length, 100.0, 1e-9); // not tool.tbl's 95.5 as loaded, nor [tools]'
    EXPECT_NEAR(s.tool(2)->diameter, 18.0, 1e-9);
    // the fixed setter of a FANUC: its input wired (575), params 135/136 and [tool_setter]
    ASSERT_EQ(s.setters.size(), 1u);
    EXPECT_EQ(s.setters[0].x, 400.0);
    EXPECT_EQ(s.setters[0].y, -50.0);
    EXPECT_EQ(s.setters[0].top, -450.0);
    EXPECT_EQ(s.setters[0].radius, 6.35);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::None);
}

TEST(MachineScene, FixedAndFloatingSettersStandAtTheirParameters) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    MachineScene s = preview::buildScene(c);
    ASSERT_EQ(s.setters.size(), 2u);
    EXPECT_EQ(s.setters[0].kind, SceneSetter::Kind::Fixed);
    EXPECT_EQ(s.setters[0].x, 555.269); // param 135
    EXPECT_EQ(s.setters[0].y, 66.381);  // param 136
    EXPECT_EQ(s.setters[0].top, -120.0); // [tool_setter] top
    EXPECT_EQ(s.setters[0].radius, 5.0);
    EXPECT_EQ(s.setters[1].kind, SceneSetter::Kind::Floating);
    EXPECT_EQ(s.setters[1].top, -122.5); // [floating_setter] top
    ASSERT_TRUE(levelOf(s, "scene_level_setter_start"));
    EXPECT_EQ(levelOf(s, "scene_level_setter_start")->z, -30.0); // param 137

    ASSERT_TRUE(c.setParameter(135, 400.0));
    ASSERT_TRUE(c.setParameter(130, 0.0)); // the fixed setter switched off: not drawn
    MachineScene moved = preview::buildScene(c);
    ASSERT_EQ(moved.setters.size(), 1u);
    EXPECT_EQ(moved.setters[0].kind, SceneSetter::Kind::Floating);
    ASSERT_TRUE(c.setParameter(130, 1.0));
    EXPECT_EQ(preview::buildScene(c).setters[0].x, 400.0);
    ASSERT_TRUE(c.setParameter(128, 0.0)); // the floating setter switched off
    EXPECT_EQ(preview::buildScene(c).setters.size(), 1u);
}

TEST(MachineScene, TravelIsTheSoftLimitBoxWhenTheyAreOn) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    MachineScene derived = preview::buildScene(c);
    EXPECT_FALSE(derived.travelFromSoftLimits);
    // param 155 off: the box around the folder's positions, pockets 50..590 and the setter at 555
    EXPECT_LE(derived.travel.low.x, 0.0);
    EXPECT_GE(derived.travel.high.x, 590.0 + 50.0);
    EXPECT_LT(derived.travel.low.z, -120.0);
    EXPECT_LT(derived.table.high.z, derived.travel.low.z);

    const std::map<int, double> limits{{155, 1}, {161, -10}, {162, -20}, {163, -300}, {166, 800}, {167, 500}, {168, 5}};
    for (auto [n, v] : limits) {
        ASSERT_TRUE(c.setParameter(n, v)) << n;
    }
    MachineScene s = preview::buildScene(c);
    EXPECT_TRUE(s.travelFromSoftLimits);
    EXPECT_EQ(s.travel.low, (preview::ScenePoint{-10.0, -20.0, -300.0}));
    EXPECT_EQ(s.travel.high, (preview::ScenePoint{800.0, 500.0, 5.0}));
    EXPECT_EQ(s.table.low.x, -10.0);
    EXPECT_EQ(s.table.high.y, 500.0);
    EXPECT_LT(s.table.high.z, -300.0);

    ASSERT_TRUE(c.setParameter(155, 0.0)); // off: the limits guard nothing, the box is derived again
    EXPECT_FALSE(preview::buildScene(c).travelFromSoftLimits);
}

TEST(MachineScene, WorkZeroFollowsTheActiveSystemsOffsets) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.workSystem, "G54");
    // offsets.toml G54 = [300, 200, -12.5]; T1's Z offset -53.677 and length 66.323: its tip at
    // work Z 0 stands at G54 Z + the setter's top
    EXPECT_NEAR(s.workZero.x, 300.0, 1e-9);
    EXPECT_NEAR(s.workZero.y, 200.0, 1e-9);
    EXPECT_NEAR(s.workZero.z, -12.5 - 120.0, 1e-9);
    EXPECT_NEAR(s.setters[1].x, 300.0, 1e-9); // the floating block lies on the work there

    ASSERT_TRUE(c.setVariable(805, 100.0)); // G54 X
    MachineScene moved = preview::buildScene(c);
    EXPECT_NEAR(moved.workZero.x, 100.0, 1e-9);
    EXPECT_NE(moved, s);

    ASSERT_RAN(mdi(c, {"G55"}));
    MachineScene g55 = preview::buildScene(c);
    EXPECT_EQ(g55.workSystem, "G55");
    EXPECT_NEAR(g55.workZero.x, 0.0, 1e-9);
}

TEST(MachineScene, ADroppedToolLiesOnTheTable) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    controller::RunReport r = mdi(c, {"G53 X300 Y250", "M154"}); // release T1 over the table
    ASSERT_TRUE(r.alarm);
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.spindleTool, 0);
    ASSERT_EQ(s.fallen.size(), 1u);
    EXPECT_EQ(s.fallen[0].tool, 1);
    EXPECT_EQ(s.fallen[0].at, (preview::ScenePoint{300.0, 250.0, s.table.high.z}));
    ASSERT_TRUE(s.tool(1));
}

TEST(MachineScene, ServoDiscPocketsStandOnACircleThroughTheStation) {
    controller::Controller c(bundledMachine("m350-servo-disc"), {});
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::ServoDisc);
    ASSERT_EQ(s.magazine.pockets.size(), 10u); // param 801
    EXPECT_GT(s.magazine.radius, 0.0);
    const preview::ScenePoint station{650.0, 20.0, -85.0}; // params 808, 809, 807
    EXPECT_TRUE(s.magazine.pockets[0].atStation);
    EXPECT_NEAR(distanceXY(s.magazine.pockets[0].at, station), 0.0, 1e-9);
    for (const preview::ScenePocket& pocket : s.magazine.pockets) {
        EXPECT_NEAR(distanceXY(pocket.at, s.magazine.centre), s.magazine.radius, 1e-9);
        EXPECT_EQ(pocket.at.z, -85.0);
    }
    ASSERT_TRUE(levelOf(s, "scene_level_change_down"));

    ASSERT_RAN(mdi(c, {"T3"}));
    MachineScene after = preview::buildScene(c);
    EXPECT_EQ(after.spindleTool, 3);
    EXPECT_TRUE(after.magazine.pockets[2].atStation);
    EXPECT_FALSE(after.magazine.pockets[0].atStation);
    EXPECT_NEAR(distanceXY(after.magazine.pockets[2].at, station), 0.0, 1e-9); // the disc turned
    EXPECT_EQ(after.magazine.pockets[2].tool, 0);
    EXPECT_EQ(after.magazine.pockets[0].tool, 1);
    EXPECT_EQ(after.magazine.centre, s.magazine.centre);
}

TEST(MachineScene, UmbrellaCarouselTurnsAndSlides) {
    controller::RunSettings settings;
    settings.tool = 3;
    controller::Controller c(bundledMachine("fanuc-umbrella"), settings);
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::Umbrella);
    ASSERT_EQ(s.magazine.pockets.size(), 12u);
    EXPECT_EQ(s.magazine.slide, 0.0); // away
    EXPECT_TRUE(s.magazine.pockets[2].atStation); // T3's empty clip faces the spindle
    const preview::ScenePoint change{0.0, 0.0, -125.0}; // reference point 3
    EXPECT_GT(distanceXY(s.magazine.pockets[2].at, change), 1.0); // away from the spindle
    ASSERT_TRUE(levelOf(s, "scene_level_carousel_clear"));
    EXPECT_EQ(levelOf(s, "scene_level_carousel_clear")->z, -20.0); // reference point 2
    EXPECT_EQ(levelOf(s, "scene_level_carousel_grip")->z, -125.0);
    EXPECT_NEAR(s.tool(5)->length, 97.5, 1e-9); // [tools] length: no offsets in memory

    ASSERT_RAN(mdi(c, {"G90 G21", "M06 T5"}));
    MachineScene after = preview::buildScene(c);
    EXPECT_EQ(after.spindleTool, 5);
    EXPECT_TRUE(after.magazine.pockets[4].atStation); // turned to T5's clip
    EXPECT_FALSE(after.magazine.pockets[2].atStation);
    EXPECT_EQ(after.magazine.pockets[2].tool, 3);
    EXPECT_EQ(after.magazine.pockets[4].tool, 0);
    EXPECT_EQ(after.magazine.slide, 0.0); // back again (M84)

    // in: slid to the spindle, the clip at the spindle stands at the change point
    ASSERT_RAN(mdi(c, {"M19", "G91 G30 P3 Z0", "M81", "M83"}));
    MachineScene in = preview::buildScene(c);
    EXPECT_EQ(in.magazine.slide, 1.0);
    EXPECT_NEAR(distanceXY(in.magazine.pockets[4].at, change), 0.0, 1e-9);
    EXPECT_NE(in.magazine.centre, after.magazine.centre);
}

TEST(MachineScene, MultiProcessHeadsRideTheSpindleAndTheOneDownIsMarked) {
    controller::Controller c(bundledMachine("m350-multi-head"), {});
    MachineScene s = preview::buildScene(c);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::MultiHead);
    EXPECT_TRUE(s.magazine.followsSpindle);
    ASSERT_EQ(s.magazine.pockets.size(), 4u);
    EXPECT_TRUE(s.magazine.pockets[0].atStation); // head 1 down at power-on (param 800)
    EXPECT_FALSE(s.magazine.pockets[2].atStation);
    EXPECT_EQ(s.magazine.pockets[2].tool, 3);
    ASSERT_RAN(mdi(c, {"T3"}));
    MachineScene after = preview::buildScene(c);
    EXPECT_FALSE(after.magazine.pockets[0].atStation);
    EXPECT_TRUE(after.magazine.pockets[2].atStation);
    EXPECT_EQ(after.spindleTool, 3);
    ASSERT_TRUE(c.setParameter(892, 120.0)); // head 3's X offset from the spindle
    EXPECT_EQ(preview::buildScene(c).magazine.pockets[2].at.x, 120.0);
}

TEST(MachineScene, AGantryRowsForksFollowTheSpindleInY) {
    controller::Controller c(bundledMachine("m350-follow-row"), {});
    MachineScene s = preview::buildScene(c);
    EXPECT_TRUE(s.magazine.onGantry);
    ASSERT_EQ(s.magazine.pockets.size(), 6u);
    EXPECT_EQ(s.magazine.pockets[2].at.x, 300.0); // param 832
    EXPECT_EQ(s.magazine.pockets[2].at.z, -90.0); // param 872
    // slide in: the forks stand slide_travel (100 mm) from the spindle in Y
    EXPECT_EQ(s.magazine.pockets[2].at.y, c.displayPosition()(1) - 100.0);
    ASSERT_RAN(mdi(c, {"G53 Y250"}));
    EXPECT_EQ(preview::buildScene(c).magazine.pockets[2].at.y, 150.0);
    ASSERT_RAN(mdi(c, {"T3"}));
    MachineScene after = preview::buildScene(c);
    EXPECT_EQ(after.spindleTool, 3);
    EXPECT_EQ(after.magazine.pockets[2].tool, 0);
}

TEST(MachineScene, ATopLoadingRackAndAMachineWithoutMagazine) {
    controller::Controller top(bundledMachine("m350-rack-top"), {});
    EXPECT_TRUE(preview::buildScene(top).magazine.topLoading);

    controller::Controller manual(bundledMachine("m350-manual"), {});
    MachineScene s = preview::buildScene(manual);
    EXPECT_EQ(s.magazine.kind, SceneMagazine::Kind::None);
    EXPECT_TRUE(s.magazine.pockets.empty());
    EXPECT_EQ(s.spindleTool, 1);
    EXPECT_NEAR(s.tool(1)->length, 68.5, 1e-9);
    ASSERT_TRUE(levelOf(s, "scene_level_manual_change")); // param 818
}

// What the panel publishes: the same object while nothing changed, a new one when a tool moved.
TEST(MachineScene, ASharedSceneIsReplacedOnlyWhenItChanged) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    std::shared_ptr<const MachineScene> first = preview::sceneSince(nullptr, c);
    ASSERT_TRUE(first);
    EXPECT_EQ(preview::sceneSince(first, c), first);
    ASSERT_RAN(mdi(c, {"G53 X100"})); // the spindle moved: no part of the scene
    EXPECT_EQ(preview::sceneSince(first, c), first);
    ASSERT_RAN(mdi(c, {"T2"}));
    std::shared_ptr<const MachineScene> second = preview::sceneSince(first, c);
    EXPECT_NE(second, first);
    EXPECT_EQ(second->spindleTool, 2);
}

// A disc turning in display time: the pockets go round between the two stations.
TEST(MachineScene, ADiscTurningStandsBetweenItsPockets) {
    controller::Controller c(bundledMachine("m350-servo-disc"), {});
    ASSERT_TRUE(c.loadMdi({"T3"}));
    ASSERT_TRUE(c.start());
    const preview::ScenePoint station{650.0, 20.0, -85.0};
    bool between = false;
    for (int frame = 0; frame < 4000 && c.runState() == controller::RunState::Running; ++frame) {
        c.advance(0.02);
        MachineScene s = preview::buildScene(c);
        double nearest = 1e9;
        for (const preview::ScenePocket& pocket : s.magazine.pockets) {
            nearest = std::min(nearest, distanceXY(pocket.at, station));
        }
        between = between || nearest > 1.0; // mid-turn: no pocket faces the station
    }
    EXPECT_TRUE(between) << "no frame showed the disc between two pockets";
    MachineScene end = preview::buildScene(c);
    EXPECT_NEAR(distanceXY(end.magazine.pockets[2].at, station), 0.0, 1e-9);
}

// The panel builds a scene every frame and compares it with the last: that must cost microseconds.
TEST(MachineScene, BuildingAndComparingIsCheap) {
    controller::Controller c(bundledMachine("m350-linear16"), {});
    MachineScene last = preview::buildScene(c);
    constexpr int kFrames = 2000;
    const auto start = std::chrono::steady_clock::now();
    int differed = 0;
    for (int i = 0; i < kFrames; ++i) {
        MachineScene next = preview::buildScene(c);
        differed += next == last ? 0 : 1;
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / kFrames;
    RecordProperty("scene_build_compare_us", std::to_string(us));
    EXPECT_EQ(differed, 0);
    EXPECT_LT(us, 500.0); // a frame is 16 ms; measured a few microseconds (README)
}

} // namespace
