// The umbrella carousel (斗笠式刀库) of the FANUC paper: the device alone, then the bundled machine
// running the paper's O9001 through M06: exchange, return only (T0), fetch into an empty spindle,
// same tool, a T the carousel does not have; the crashes a wrong line causes; sensors that never
// come; and a 100-change soak.
#include "core/devices/UmbrellaCarousel.h"

#include "RunProgram.h"
#include "TracedRun.h"
#include "ShippedMacros.h"

#include <gtest/gtest.h>

#include <chrono>
#include <random>

namespace {

using namespace m350;
using namespace m350::test;
using devices::UmbrellaCarousel;
using Eigen::Vector3d;

constexpr const char* kUmbrella = "fanuc-umbrella";

// Six pockets, T2 in the spindle, its empty pocket at the spindle; change height Z-100, clear Z0.
UmbrellaCarousel carousel() {
    UmbrellaCarousel::Geometry g;
    g.gripZ = -100.0;
    g.clearZ = 0.0;
    g.pockets = 6;
    return UmbrellaCarousel(g, {1, 0, 3, 4, 5, 6}, 2, 2);
}

TEST(UmbrellaDevice, AnExchangeLeavesTheOldToolInItsClipAndTakesTheNew) {
    UmbrellaCarousel c = carousel();
    c.spindle(false, true); // stopped and oriented (M19)
    EXPECT_FALSE(c.move({0, 0, 0}, {0, 0, -100}, true, false, 0.0)); // the carousel is away: free
    EXPECT_FALSE(c.slide(true, {0, 0, -100}, 1.0).crash);
    EXPECT_FALSE(c.drawbar(true, {0, 0, -100}));
    EXPECT_EQ(c.pocketTool(2), 2);
    EXPECT_FALSE(c.move({0, 0, -100}, {0, 0, 0}, true, false, 3.0));
    EXPECT_FALSE(c.turnTo(5, {0, 0, 0}, 4.0).crash);
    EXPECT_FALSE(c.move({0, 0, 0}, {0, 0, -100}, true, false, 6.0));
    EXPECT_FALSE(c.drawbar(false, {0, 0, -100}));
    EXPECT_FALSE(c.slide(false, {0, 0, -100}, 7.0).crash);
    EXPECT_EQ(c.spindleTool(), 5);
    EXPECT_EQ(c.pocketTool(5), 0);
    EXPECT_FALSE(c.atSpindle());
}

TEST(UmbrellaDevice, TurningWithTheSpindleInsideIsACrash) {
    UmbrellaCarousel c = carousel();
    c.spindle(false, true);
    ASSERT_FALSE(c.slide(true, {0, 0, -100}, 0.0).crash);
    auto turn = c.turnTo(4, {0, 0, -100}, 2.0);
    ASSERT_TRUE(turn.crash);
    EXPECT_EQ(*turn.crash, "the carousel turned from pocket 2 to pocket 4 while the spindle was inside it at "
                           "X0.000 Y0.000 Z-100.000: raise Z above the tools (G30 P2) before turning it");
}

TEST(UmbrellaDevice, ComingInAtTheWrongPocketOrPlace) {
    UmbrellaCarousel c = carousel();
    c.spindle(false, true);
    ASSERT_FALSE(c.turnTo(3, {0, 0, 0}, 0.0).crash);
    auto occupied = c.slide(true, {0, 0, -100}, 5.0);
    ASSERT_TRUE(occupied.crash);
    EXPECT_EQ(*occupied.crash, "T2 in the spindle ran into T3 in pocket 3: the pocket at the spindle must be the "
                               "empty one of the tool being returned");
    UmbrellaCarousel d = carousel();
    d.spindle(false, true);
    auto away = d.slide(true, {40, 0, -100}, 0.0);
    ASSERT_TRUE(away.crash);
    EXPECT_EQ(*away.crash, "the carousel slid in while the spindle stood at X40.000 Y0.000 Z-100.000, away from "
                           "the change position X0.000 Y0.000: it hit the spindle head");
}

TEST(UmbrellaDevice, ReleasingWithTheCarouselAwayDropsTheTool) {
    UmbrellaCarousel c = carousel();
    auto drop = c.drawbar(true, {0, 0, -100});
    ASSERT_TRUE(drop);
    EXPECT_EQ(*drop, "T2 dropped: the spindle released it at X0.000 Y0.000 Z-100.000 with the carousel away from "
                     "the spindle (slide it in with M83 first)");
    ASSERT_EQ(c.droppedTools().size(), 1u);
    EXPECT_EQ(c.droppedTools()[0].tool, 2);
    EXPECT_EQ(c.droppedTools()[0].at, Eigen::Vector3d(0, 0, -100));
}

// The bundled machine with `tool` in the spindle, one controller for several MDI changes.
struct Umbrella {
    explicit Umbrella(int tool, controller::RunSettings settings = {}) : c(machine(), with(settings, tool)) {}
    static config::MachineConfig machine() { return bundledMachine(kUmbrella); }
    static controller::RunSettings with(controller::RunSettings s, int tool) {
        s.tool = tool;
        return s;
    }
    controller::RunReport mdi(std::initializer_list<std::string> lines) {
        EXPECT_TRUE(c.loadMdi(lines)) << gcode::formatDiagnostic(c.diagnostics().at(0));
        return c.run();
    }
    controller::Controller c;
};

#define ASSERT_OK(r) ASSERT_EQ((r).status, controller::RunStatus::Ok) << ((r).alarm ? (r).alarm->message : "")

TEST(UmbrellaMachine, ExchangeReturnsTheOldToolAndRestoresTheModes) {
    Umbrella u(3);
    controller::RunReport r = u.mdi({"G90 G21", "M06 T5"});
    ASSERT_OK(r);
    EXPECT_EQ(r.tool, 5);
    EXPECT_EQ(r.pockets.at(3), 3);
    EXPECT_EQ(r.pockets.at(5), 0);
    EXPECT_EQ(u.c.variable(1000).number, 1); // M85 stored T5: the commanded T is in the spindle
    EXPECT_EQ(u.c.variable(4003).number, 90); // the macro's G91 undone (N280)
    EXPECT_EQ(u.c.variable(4006).number, 21);
    EXPECT_EQ(r.machine(2), -125.0); // it ends at the change height, as the paper's flow does
    RecordProperty("exchange_sim_s", std::to_string(r.simTime));
    EXPECT_GT(r.simTime, 4.0);
    EXPECT_LT(r.simTime, 15.0);
}

TEST(UmbrellaMachine, ThePmcFinishesEachMCodeWhenItsSensorSaysSo) {
    controller::RunSettings settings;
    settings.tool = 3;
    TracedRun t = runTraced(bundledMachine(kUmbrella), "M06 T0\nM30\n", settings);
    EXPECT_RUN_OK(t.run);
    // the return only: carousel in (1.2 s to IN05), release (0.3 s to IN11), up, clamp, back
    const std::vector<std::string> expected{
        "M81", "M83", "OUT03=1 at 0.601", "IN06=0 at 0.601", "IN05=1 at 1.801",
        "M11", "OUT01=1 at 2.3012", "IN11=1 at 2.6012", "IN12=0 at 2.6012",
        "M10", "OUT01=0 at 3.6316", "IN11=0 at 3.9316", "IN12=1 at 3.9316",
        "M85", "M84", "OUT03=0 at 3.9418", "IN05=0 at 3.9418", "IN06=1 at 5.1418"};
    EXPECT_EQ(t.signals, expected);
}

TEST(UmbrellaMachine, T0ReturnsOnlyAndAFetchFillsTheEmptySpindle) {
    Umbrella u(3);
    controller::RunReport r = u.mdi({"M06 T0"});
    ASSERT_OK(r);
    EXPECT_EQ(r.tool, 0);
    EXPECT_EQ(r.pockets.at(3), 3);
    EXPECT_EQ(u.c.variable(1001).number, 1); // the spindle's tool is 0 now
    r = u.mdi({"M06 T8"});
    ASSERT_OK(r);
    EXPECT_EQ(r.tool, 8);
    EXPECT_EQ(r.pockets.at(8), 0);
    EXPECT_EQ(r.pockets.at(3), 3);
}

TEST(UmbrellaMachine, TheSameToolDoesNothingAndAToolItDoesNotHaveIsRefused) {
    Umbrella u(4);
    controller::RunReport r = u.mdi({"M06 T4"});
    ASSERT_OK(r);
    EXPECT_LT(r.simTime, 0.01);
    r = u.mdi({"M06 T13"});
    ASSERT_TRUE(r.alarm);
    EXPECT_EQ(r.alarm->code, AlarmCode::InvalidArgument);
    EXPECT_EQ(r.alarm->message, "T13 is not in the carousel: its pockets are 1-12 (the PMC refused the T code; "
                                "nothing moved)");
    EXPECT_EQ(r.alarm->column, 5u) << "at the T word";
    EXPECT_EQ(r.tool, 4);
    EXPECT_LT(r.simTime, 0.01) << "refused before O9001 oriented the spindle or moved Z";
}

// O9001 with one line made wrong, carried by the program file: "M06 T5" with T3 in the spindle.
ProgramRun exchangeWith(const std::string& right, const std::string& wrong, controller::RunSettings settings = {}) {
    settings.tool = 3;
    std::string program = "M06 T5\nM30\n" + withLine(shippedLibrary(kUmbrella, "O9001.nc"), right, wrong);
    return runProgram(bundledMachine(kUmbrella), program, std::move(settings));
}

void expectAlarm(const ProgramRun& r, AlarmCode code, const std::string& message, const std::string& line) {
    ASSERT_TRUE(r.report.alarm) << "no alarm";
    EXPECT_EQ(r.report.alarm->code, code) << r.alarmText();
    EXPECT_EQ(r.report.alarm->message, message);
    EXPECT_EQ(r.report.alarm->line, lineOf("M06 T5\nM30\n" + shippedLibrary(kUmbrella, "O9001.nc"), line));
}

TEST(UmbrellaMachine, WithoutOrientingTheClipHitsTheHolder) {
    ProgramRun r = exchangeWith("N50 G91M19", "N50 G91");
    expectAlarm(r, AlarmCode::Crash,
                "the clip of pocket 3 hit T3's holder out of line with its key: orient the spindle (M19) first",
                "N90 M83");
}

TEST(UmbrellaMachine, RisingBeforeReleasingTearsTheToolOutOfTheCarousel) {
    ProgramRun r = exchangeWith("N110 M11 (主軸松刀 release)", "N110 (M11 forgotten)");
    expectAlarm(r, AlarmCode::Crash,
                "Z moved from X0.000 Y0.000 Z-125.000 to X0.000 Y0.000 Z-20.000 while T3 was clamped in the spindle "
                "and held by the clip of pocket 3: release it (M11) first, or slide the carousel back (M84)",
                "N130 G91 G30 P2 Z0");
}

TEST(UmbrellaMachine, ReleasingBeforeTheCarouselIsThereDropsTheTool) {
    ProgramRun r = exchangeWith("N90 M83 (刀庫向右靠近主軸 carousel to the spindle)", "N90 (M83 forgotten)");
    expectAlarm(r, AlarmCode::Crash,
                "T3 dropped: the spindle released it at X0.000 Y0.000 Z-125.000 with the carousel away from the "
                "spindle (slide it in with M83 first)",
                "N110 M11");
}

TEST(UmbrellaMachine, NotTurningTheCarouselFetchesTheOldToolAgain) {
    // no crash: the spindle takes T3 back from its own clip while M85 stores T5 — the report shows
    // the tool the spindle really holds, and #1000 says the controller believes otherwise
    ProgramRun r = exchangeWith("N150 M82 (刀盤旋轉 turn the carousel)", "N150");
    EXPECT_RUN_OK(r);
    EXPECT_EQ(r.report.tool, 3);
    EXPECT_EQ(r.report.pockets.at(3), 0);
    EXPECT_EQ(r.report.pockets.at(5), 5);
}

TEST(UmbrellaMachine, ACarouselSensorThatNeverComesStopsTheRunNamingIt) {
    controller::RunSettings settings;
    settings.sensorTimeout = 2.0;
    settings.heldInputs[5] = 0; // IN05 "carousel at the spindle" stuck off
    ProgramRun r = exchangeWith("", "", settings);
    expectAlarm(r, AlarmCode::SensorTimeout,
                "IN05 (carousel at the spindle) never became 1: the PMC waited 2.0 s to finish M83", "N90 M83");
    EXPECT_EQ(r.report.outputs[2], 0); // the carousel's valve back at rest
}

TEST(UmbrellaMachine, ASlowClampSensorOnlyMakesTheChangeLonger) {
    Umbrella fast(3);
    Umbrella slow(3);
    slow.c.setInputFault(12, machine::InputFault::delayed(1.5));
    controller::RunReport a = fast.mdi({"M06 T5"});
    controller::RunReport b = slow.mdi({"M06 T5"});
    ASSERT_OK(b);
    EXPECT_EQ(b.tool, 5);
    EXPECT_NEAR(b.simTime - a.simTime, 1.5, 0.05); // the PMC waits for the clamp once
}

TEST(UmbrellaMachine, HundredRandomChangesLeaveEveryToolAccountedFor) {
    Umbrella u(1);
    std::mt19937 random(20261123);
    std::uniform_int_distribution<int> pick(0, 12);
    int expected = 1;
    double slowest = 0.0;
    const auto wallStart = std::chrono::steady_clock::now();
    for (int change = 0; change < 100; ++change) {
        const int target = pick(random);
        const double before = u.c.status().report().simTime;
        controller::RunReport r = u.mdi({"M06 T" + std::to_string(target)});
        ASSERT_OK(r) << " at change " << change << " to T" << target;
        slowest = std::max(slowest, r.simTime - before);
        expected = target;
        ASSERT_EQ(r.tool, expected) << "change " << change;
        for (int pocket = 1; pocket <= 12; ++pocket) {
            ASSERT_EQ(r.pockets.at(pocket), pocket == expected ? 0 : pocket) << "change " << change;
        }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    RecordProperty("slowest_change_sim_s", std::to_string(slowest));
    RecordProperty("soak_wall_s", std::to_string(wall));
    EXPECT_GT(slowest, 4.0);
    EXPECT_LT(slowest, 15.0);
}

} // namespace
