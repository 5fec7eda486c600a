// A straight move nothing listens to makes no machine event (MachineObserver::ignoresMove): the
// machine still takes its time and goes where it leads; what would need the event still gets it
// (an arc, a linked input falling due, a rack the move comes near, a trace, an observer, cutting
// time).
#include "TracedRun.h"
#include "ToolLifeFixture.h"

#include "core/machine/SimulatedMachine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

namespace {

using namespace m350;
using namespace m350::test;
using machine::Axes;
using machine::MachineEvent;
using machine::SimulatedMachine;

Axes at(double x, double y = 0, double z = 0) {
    Axes a = Axes::Zero();
    a << x, y, z, 0, 0;
    return a;
}

struct Recorder : machine::MachineObserver {
    bool ignoring = false;
    std::vector<MachineEvent> events;
    void onMachineEvent(const MachineEvent& e) override { events.push_back(e); }
    bool ignoresMove(const Axes&, const Axes&) const override { return ignoring; }
};

TEST(IgnoredMove, AStraightMoveTheObserverIgnoresTakesItsTimeWithoutAnEvent) {
    Recorder quiet;
    quiet.ignoring = true;
    Recorder told;
    SimulatedMachine a(&quiet);
    SimulatedMachine b(&told);
    for (SimulatedMachine* m : {&a, &b}) {
        m->feed(at(100, 20), 3000);
        m->rapid(at(-30, 5, 10));
        m->manualMove(at(0, 0, 0), 50.0, 500.0);
    }
    EXPECT_TRUE(quiet.events.empty());
    EXPECT_EQ(told.events.size(), 3u);
    EXPECT_EQ(a.time(), b.time());
    EXPECT_EQ(a.position(), b.position());
    EXPECT_EQ(a.positionAt(a.time() - 0.05), b.positionAt(b.time() - 0.05)); // the last move is still known
}

TEST(IgnoredMove, AnArcIsAlwaysReported) {
    Recorder quiet;
    quiet.ignoring = true;
    SimulatedMachine m(&quiet);
    m.setPosition(at(10));
    const auto arc = machine::makeArc({at(10), at(-10), machine::Plane::XY, false, Eigen::Vector3d(-10, 0, 0),
                                       std::nullopt, 0});
    ASSERT_TRUE(std::holds_alternative<machine::Arc>(arc));
    m.arc(std::get<machine::Arc>(arc), 600);
    ASSERT_EQ(quiet.events.size(), 1u);
    EXPECT_EQ(quiet.events[0].type, MachineEvent::Type::Arc);
    ASSERT_NE(quiet.events[0].arc, nullptr);
}

// A linked input that fell due is reported with the next event: a move then makes one, so the
// observer hears of the input when it would have.
TEST(IgnoredMove, AMoveIsReportedWhileALinkedInputWaitsToBe) {
    Recorder quiet;
    quiet.ignoring = true;
    SimulatedMachine m(&quiet);
    m.addLink({1, 11, 0.15, false});
    m.setOutput(1, 1); // IN11 follows 0.15 s later
    m.dwell(1.0);
    m.feed(at(100), 3000);
    m.feed(at(0), 3000); // nothing waits any more: ignored
    ASSERT_EQ(quiet.events.size(), 4u);
    EXPECT_EQ(quiet.events[0].port, 1); // OUT01
    EXPECT_EQ(quiet.events[1].type, MachineEvent::Type::Dwell);
    EXPECT_EQ(quiet.events[2].port, -11); // IN11, at 0.15 s
    EXPECT_DOUBLE_EQ(quiet.events[2].start, 0.15);
    EXPECT_EQ(quiet.events[3].type, MachineEvent::Type::Feed);
    EXPECT_DOUBLE_EQ(quiet.events[3].start, 1.0);
}

// Work X Y Z 0..100 on the default machine is machine X 300..400 Y 200, far from its rack (Y 5).
const char* const kFarMoves[] = {"G90 G0 X0 Y0 Z20", "G1 X100 F600", "G1 Y50", "G1 X0 Z10", "M30"};

std::string farProgram() {
    std::string text;
    for (const char* line : kFarMoves) {
        text += std::string(line) + "\n";
    }
    return text;
}

TEST(IgnoredMove, TheRunsObserverSeesEveryMoveFarFromTheRack) {
    Recorder observer;
    controller::RunSettings settings;
    settings.observer = &observer;
    ProgramRun run = runProgram(bundledMachine(), farProgram(), settings);
    EXPECT_RUN_OK(run);
    const auto feeds = std::count_if(observer.events.begin(), observer.events.end(),
                                     [](const MachineEvent& e) { return e.type == MachineEvent::Type::Feed; });
    EXPECT_EQ(feeds, 3);
}

TEST(IgnoredMove, TheTraceHasEveryMoveFarFromTheRack) {
    TracedRun traced = runTraced(bundledMachine(), farProgram());
    EXPECT_RUN_OK(traced.run);
    const auto feeds = std::count_if(traced.events.begin(), traced.events.end(),
                                     [](const std::string& e) { return e.rfind("feed ", 0) == 0; });
    EXPECT_EQ(feeds, 3);
}

TEST(IgnoredMove, CuttingTimeCountsTheMovesFarFromTheRack) {
    config::MachineConfig config = bundledMachine();
    config.toolLife.putGroup(group(1, 1, tools::LifeKind::Minutes, {{3, 0, 0, 0}, {4, 0, 0, 0}}));
    // 100 + 50 + 100.5 mm at F600 (10 mm/s), about 25 s: 6 units of 4 s; none when the moves went uncounted
    ProgramRun run = runProgram(config, "T101\n" + farProgram());
    EXPECT_RUN_OK(run);
    EXPECT_EQ(used(run, 1, 3), 6);
}

TEST(IgnoredMove, TheSpindleLoadFollowsTheMovesFarFromTheRack) {
    config::MachineConfig config = bundledMachine();
    machine::SpindleLoadModel model;
    model.stock = machine::Stock{};
    model.stock->top = 1000.0; // every move cuts
    config.spindleLoad = model;
    ProgramRun run = runProgram(config, "S6000 M03\n" + farProgram());
    EXPECT_RUN_OK(run);
    const auto& history = run.controller->toolBreakage().spindleLoad().monitor().history();
    // sampled while the feed moves lasted; with their events left out, only at the spindle's events
    EXPECT_TRUE(std::any_of(history.begin(), history.end(), [](const tools::LoadSample& s) { return s.cutting; }));
}

} // namespace
