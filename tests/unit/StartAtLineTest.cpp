// 断点加工 Break Run: a program started at a line runs the blocks before it as a scan (state, no
// motion, no time), approaches the program's position (Z up, XY over, Z down at feed) and goes on;
// after PAUSE and RESET it resumes at the paused block.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using namespace m350;
using namespace m350::test;
using RunState = controller::Controller::RunState;
using Type = machine::MachineEvent::Type;

struct Recorder : machine::MachineObserver {
    std::vector<machine::MachineEvent> events;
    void onMachineEvent(const machine::MachineEvent& event) override { events.push_back(event); }
    std::vector<machine::MachineEvent> moves() const {
        std::vector<machine::MachineEvent> out;
        for (const auto& e : events) {
            if (e.type == Type::Rapid || e.type == Type::Feed || e.type == Type::Arc) {
                out.push_back(e);
            }
        }
        return out;
    }
};

config::MachineConfig machine() {
    auto cfg = m350Machine();
    cfg.parameters.set(62, 500); // G01 acceleration
    cfg.offsets[2] = {100.0, 0.0, 0.0, 0.0, 0.0}; // G55 X100
    return cfg;
}

std::unique_ptr<controller::Controller> loaded(config::MachineConfig cfg, const std::string& program,
                                               Recorder* recorder = nullptr, bool homed = true) {
    controller::RunSettings settings;
    settings.observer = recorder;
    settings.homed = homed;
    auto c = std::make_unique<controller::Controller>(std::move(cfg), settings);
    EXPECT_TRUE(c->loadFile(writeTempFile(program)));
    return c;
}

const std::string kProgram = lines({
    "G55",                // 1
    "G90 G0 X10 Y10 Z5",  // 2  machine X110 Y10 Z5
    "M3 S12000",          // 3
    "#100 = 7",           // 4
    "F600",               // 5
    "G91 G1 X5",          // 6  X115: the program is here before line 7
    "Z-3",                // 7  start here
    "X20",                // 8
    "M30",                // 9
});

TEST(StartAtLine, RebuildsTheModalStateAndApproachesZUpXYOverZDown) {
    auto cfg = machine();
    cfg.parameters.set(param::kLiftBeforeStart, 1);
    cfg.parameters.set(param::kSafeZ, 20); // G55 Z20 = machine Z20
    Recorder rec;
    auto c = loaded(std::move(cfg), kProgram, &rec);
    Message why;
    ASSERT_TRUE(c->breakRun().startAtLine(7, &why)) << why;
    EXPECT_EQ(c->runState(), RunState::Running);
    const std::string modal = c->status().modalLine();
    EXPECT_NE(modal.find("G91"), std::string::npos) << modal;
    EXPECT_NE(modal.find("G55"), std::string::npos) << modal;
    EXPECT_NE(modal.find("F600"), std::string::npos) << modal;
    EXPECT_EQ(c->variable(100).number, 7.0);

    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    auto moves = rec.moves();
    ASSERT_EQ(moves.size(), 5u);
    EXPECT_EQ(moves[0].type, Type::Rapid); // Z up to the safe height
    EXPECT_EQ(moves[0].to, (machine::Axes() << 0, 0, 20, 0, 0).finished());
    EXPECT_EQ(moves[1].type, Type::Rapid); // XY over
    EXPECT_EQ(moves[1].to, (machine::Axes() << 115, 10, 20, 0, 0).finished());
    EXPECT_EQ(moves[2].type, Type::Feed); // Z down at the program's feed
    EXPECT_EQ(moves[2].to, (machine::Axes() << 115, 10, 5, 0, 0).finished());
    EXPECT_DOUBLE_EQ(moves[2].feed, 600.0);
    EXPECT_EQ(moves[3].to, (machine::Axes() << 115, 10, 2, 0, 0).finished()); // line 7, incremental
    EXPECT_EQ(moves[4].to, (machine::Axes() << 135, 10, 2, 0, 0).finished()); // line 8

    // the spindle came on (M3 S12000) before the XY move, and the scan took no time
    auto spindle = std::find_if(rec.events.begin(), rec.events.end(), [](const auto& e) { return e.type == Type::Spindle; });
    ASSERT_NE(spindle, rec.events.end());
    EXPECT_EQ(spindle->spindle, machine::SpindleState::Forward);
    EXPECT_DOUBLE_EQ(spindle->rpm, 12000.0);
    EXPECT_LE(spindle->end, moves[1].start);
    EXPECT_DOUBLE_EQ(moves[0].start, 0.0);
}

TEST(StartAtLine, WithoutParam90ZRisesOnlyToTheHigherOfTheTwo) {
    Recorder rec;
    auto c = loaded(machine(), kProgram, &rec);
    Message why;
    ASSERT_TRUE(c->breakRun().startAtLine(7, &why)) << why;
    c->advance(100.0);
    auto moves = rec.moves();
    ASSERT_GE(moves.size(), 2u);
    EXPECT_EQ(moves[0].to, (machine::Axes() << 0, 0, 5, 0, 0).finished()); // up to the program's Z5
    EXPECT_EQ(moves[1].to, (machine::Axes() << 115, 10, 5, 0, 0).finished());
    EXPECT_EQ(moves[2].to, (machine::Axes() << 115, 10, 2, 0, 0).finished()); // no Z down: already there
}

TEST(StartAtLine, ABlankLineStartsAtTheNextBlockAndAJumpIsFollowed) {
    Recorder rec;
    auto c = loaded(machine(), lines({"#1 = 2", "GOTO 10", "G0 X99", "N10 G0 X1", "", "G0 X2", "M30"}), &rec);
    Message why;
    ASSERT_TRUE(c->breakRun().startAtLine(5, &why)) << why;
    c->advance(100.0);
    auto moves = rec.moves();
    ASSERT_EQ(moves.size(), 2u); // over to X1 (where line 4 left the program), then line 6
    EXPECT_DOUBLE_EQ(moves[0].to(0), 1.0);
    EXPECT_DOUBLE_EQ(moves[1].to(0), 2.0);
}

TEST(StartAtLine, Refusals) {
    const std::string program = lines({"G91", "GOTO 4", "G0 X99", "N4 G0 X1", "M98 P100", "M30", "O100", "G0 Y1", "M99"});
    auto c = loaded(machine(), program);
    Message why;
    EXPECT_FALSE(c->breakRun().startAtLine(40, &why));
    EXPECT_NE(why.english().find("is not in"), std::string::npos) << why;
    EXPECT_FALSE(c->breakRun().startAtLine(0, &why));
    EXPECT_FALSE(c->breakRun().startAtLine(8, &why));
    EXPECT_NE(why.english().find("O100, a subprogram"), std::string::npos) << why;
    EXPECT_EQ(why.in(MessageLanguage::Chinese), "第8行在子程序O100中：请从调用它的主程序行开始"); // the 断点加工 page's words
    EXPECT_FALSE(c->breakRun().startAtLine(3, &why));
    EXPECT_NE(why.english().find("never reaches"), std::string::npos) << why;
    // a refusal changes nothing: G91 was scanned, but the modal state is as it was
    EXPECT_NE(c->status().modalLine().find("G90"), std::string::npos) << c->status().modalLine();
    EXPECT_EQ(c->runState(), RunState::Idle);

    ASSERT_TRUE(c->breakRun().startAtLine(4, &why)) << why;
    EXPECT_FALSE(c->breakRun().startAtLine(4, &why));
    EXPECT_NE(why.english().find("RESET first"), std::string::npos) << why;

    auto cfg = machine();
    cfg.parameters.set(param::kHomeBeforeProcessing, 1);
    auto unhomed = loaded(std::move(cfg), program, nullptr, false);
    EXPECT_FALSE(unhomed->breakRun().startAtLine(4, &why));
    EXPECT_NE(why.english().find("parameter 220"), std::string::npos) << why;
}

TEST(StartAtLine, RefusesAToolChangeBeforeTheLineOnAMachineWithAMagazine) {
    Recorder rec;
    auto c = loaded(bundledMachine(), lines({"T2", "G0 X10", "M30"}), &rec);
    Message why;
    EXPECT_FALSE(c->breakRun().startAtLine(2, &why));
    EXPECT_NE(why.english().find("tool accounting cannot be scanned"), std::string::npos) << why;
    EXPECT_TRUE(rec.moves().empty()); // nothing moved
    EXPECT_TRUE(c->breakRun().startAtLine(1, &why)) << why; // the change itself may start
}

TEST(StartAtLine, RefusesWhatAScanCannotFollow) {
    auto c = loaded(machine(), lines({"G31 X10 F100", "G0 X1", "M30"}));
    Message why;
    EXPECT_FALSE(c->breakRun().startAtLine(2, &why));
    EXPECT_NE(why.english().find("G31"), std::string::npos) << why;
    EXPECT_EQ(why.id, "scan_alarm"); // this machine has no skip input: G31 alarms in the scan
    EXPECT_NE(why.in(MessageLanguage::Chinese).find("处产生报警：G31：G31需要P<输入1-24>和L<电平>"), std::string::npos)
        << why.in(MessageLanguage::Chinese);

    auto alarmed = loaded(machine(), lines({"#3000 = 1(stop)", "G0 X1", "M30"}));
    EXPECT_FALSE(alarmed->breakRun().startAtLine(2, &why));
    EXPECT_NE(why.english().find("raise an alarm"), std::string::npos) << why;
    EXPECT_NE(why.in(MessageLanguage::Chinese).find("产生报警"), std::string::npos) << why.in(MessageLanguage::Chinese);

    auto compensating = loaded(machine(), lines({"G41 D1 G1 X10 F100", "X20", "G40 X30", "M30"}));
    EXPECT_FALSE(compensating->breakRun().startAtLine(2, &why));
    EXPECT_NE(why.english().find("G41/G42"), std::string::npos) << why;
}

// Pauses in the second pass of a loop, resets, resumes: the same pass goes on and the run ends
// where it ends uninterrupted.
const std::string kLoop = lines({
    "#100 = 0",                    // 1
    "G91",                         // 2
    "WHILE [#100 LT 3] DO1",       // 3
    "G1 X10 F600",                 // 4  1 s a pass
    "#100 = #100 + 1",             // 5
    "END1",                        // 6
    "G90 G0 Y5",                   // 7
    "M30",                         // 8
});

void pauseResetResume(double resumeMode, std::vector<machine::MachineEvent>& after, controller::RunReport& end) {
    auto cfg = machine();
    cfg.parameters.set(param::kPauseResumeMode, resumeMode);
    Recorder rec;
    auto c = loaded(std::move(cfg), kLoop, &rec);
    ASSERT_TRUE(c->start());
    c->advance(1.5); // halfway through the second pass
    c->hold();
    auto point = c->breakRun().pauseBreakPoint();
    ASSERT_TRUE(point);
    EXPECT_EQ(point->line, 4u);
    c->advance(1.0);
    c->reset();
    ASSERT_TRUE(c->breakRun().pauseBreakPoint()); // kept through RESET
    std::size_t before = rec.events.size();
    Message why;
    ASSERT_TRUE(c->breakRun().resumeAtPause(&why)) << why;
    EXPECT_FALSE(c->breakRun().pauseBreakPoint());
    EXPECT_EQ(c->advance(100.0), RunState::Finished);
    after.assign(rec.events.begin() + static_cast<std::ptrdiff_t>(before), rec.events.end());
    end = c->status().report();
    EXPECT_EQ(c->variable(100).number, 3.0);
}

TEST(ResumeAtPause, FromTheStartPointOfThePausedBlock) {
    std::vector<machine::MachineEvent> after;
    controller::RunReport end;
    pauseResetResume(0, after, end);
    ASSERT_GE(after.size(), 2u);
    EXPECT_EQ(after[0].type, Type::Rapid); // back over to X10, where the second pass began
    EXPECT_DOUBLE_EQ(after[0].to(0), 10.0);
    EXPECT_EQ(after[1].type, Type::Feed);
    EXPECT_DOUBLE_EQ(after[1].from(0), 10.0);
    EXPECT_DOUBLE_EQ(after[1].to(0), 20.0);
    EXPECT_DOUBLE_EQ(end.machine(0), 30.0); // as the uninterrupted run
    EXPECT_DOUBLE_EQ(end.machine(1), 5.0);
}

TEST(ResumeAtPause, FromThePointWhereTheHoldStoppedWithParam93) {
    std::vector<machine::MachineEvent> after;
    controller::RunReport end;
    pauseResetResume(1, after, end);
    ASSERT_GE(after.size(), 1u);
    EXPECT_EQ(after[0].type, Type::Feed); // the rest of the cut move, from where it stopped
    EXPECT_GT(after[0].from(0), 14.0);
    EXPECT_DOUBLE_EQ(after[0].to(0), 20.0);
    EXPECT_DOUBLE_EQ(end.machine(0), 30.0);
}

TEST(ResumeAtPause, NothingToResumeWithoutAPause) {
    auto c = loaded(machine(), kLoop);
    Message why;
    EXPECT_FALSE(c->breakRun().resumeAtPause(&why));
    EXPECT_NE(why.english().find("no paused run"), std::string::npos) << why;
}

} // namespace
