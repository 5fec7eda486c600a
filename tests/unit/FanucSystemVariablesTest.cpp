// System variables every FANUC 0i has that shop macros lean on: the custom macro interface signals
// (#1000-#1015, #1032 in; #1100-#1115, #1132, #1133 out) as the machine folder wires them to the
// machine, and the automatic operation control #3003 (single block) and #3004 (feed hold, feed
// override) with their effect on the run.
#include "RunProgram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

namespace {

using namespace m350;
using namespace m350::test;
using Source = config::InterfaceSignals::Source;

config::MachineConfig wiredMill() {
    config::MachineConfig machine = fanucMachine();
    config::InterfaceSignals& s = machine.interfaceSignals;
    s.inputs[0] = {Source::CommandedToolInSpindle, 0};
    s.inputs[1] = {Source::SpindleEmpty, 0};
    s.inputs[2] = {Source::T0Commanded, 0};
    s.inputs[3] = {Source::Input, 5};
    s.inputs[15] = {Source::Input, 6};
    s.outputs[0] = 7;
    s.outputs[2] = 9;
    s.wideOutputs[0] = 8;
    s.wideOutputs[31] = 10;
    return machine;
}

controller::RunSettings withInputs(std::map<int, int> levels, std::optional<int> tool = std::nullopt) {
    controller::RunSettings settings;
    settings.heldInputs = std::move(levels);
    settings.tool = tool;
    return settings;
}

std::size_t countMessages(const controller::RunReport& report, const std::string& part) {
    return static_cast<std::size_t>(
        std::count_if(report.messages.begin(), report.messages.end(),
                      [&](const std::string& m) { return m.find(part) != std::string::npos; }));
}

// --- interface signals ------------------------------------------------------------------------

TEST(InterfaceSignals, InputsReadTheWiredSignalsOneByOneAndAllAtOnce) {
    auto run = runProgram(wiredMill(),
                          lines({"T3", "#100=#1000", "#101=#1001", "#102=#1002", "#103=#1003", "#104=#1015",
                                 "#105=#1004", "#106=#1032", "T0", "#107=#1002", "M30"}),
                          withInputs({{5, 1}, {6, 1}}, 3));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 1) << "T3 is in the spindle";
    EXPECT_EQ(run.number(101), 0);
    EXPECT_EQ(run.number(102), 0);
    EXPECT_EQ(run.number(103), 1) << "IN05";
    EXPECT_EQ(run.number(104), 1) << "IN06";
    EXPECT_EQ(run.number(105), 0) << "UI004 is wired to nothing";
    EXPECT_EQ(run.number(106), 1 + 8 + 32768);
    EXPECT_EQ(run.number(107), 1);
}

TEST(InterfaceSignals, InputsAreReadOnly) {
    auto run = runProgram(wiredMill(), lines({"#1003=1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->message, "cannot write #1003 (interface input UI003): it is read-only");
    auto all = runProgram(wiredMill(), lines({"#1032=0", "M30"}));
    ASSERT_EQ(all.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(all.report.alarm->code, AlarmCode::ReadOnlyVariable);
}

TEST(InterfaceSignals, OutputsSwitchTheWiredOutputsAndReadBack) {
    auto run = runProgram(wiredMill(), lines({"#1100=1", "#100=#1100", "#101=#1132", "#1132=4", "#102=#1100",
                                              "#103=#1102", "#1133=-2147483", "#104=#1133", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 1);
    EXPECT_EQ(run.number(101), 1);
    EXPECT_EQ(run.number(102), 0) << "#1132 = 4 clears UO000";
    EXPECT_EQ(run.number(103), 1) << "and sets UO002";
    EXPECT_EQ(run.number(104), -2147483);
    const auto& out = run.report.outputs;
    EXPECT_EQ(out[6], 0) << "OUT07 follows UO000";
    EXPECT_EQ(out[8], 1) << "OUT09 follows UO002";
    // -2147483 = 0xFFDF3B65: bit 0 (UO100) on, bit 31 (UO131) on (negative)
    EXPECT_EQ(out[7], 1) << "OUT08 follows UO100";
    EXPECT_EQ(out[9], 1) << "OUT10 follows UO131";
}

TEST(InterfaceSignals, AValueAnOutputCannotTakeIsRefused) {
    struct Case {
        const char* line;
        const char* message;
    };
    for (Case c :
         {Case{"#1100=2", "#1100 = 2: an interface output is 0 or 1"},
          Case{"#1132=65536", "#1132 = 65536: it takes a whole number from 0 to 65535"},
          Case{"#1132=1.5", "#1132 = 1.5: it takes a whole number from 0 to 65535"},
          Case{"#1133=100000000", "#1133 = 100000000: it takes a whole number from -99999999 to 99999999"}}) {
        auto run = runProgram(wiredMill(), lines({c.line, "M30"}));
        ASSERT_EQ(run.report.status, controller::RunStatus::Alarm) << c.line;
        EXPECT_EQ(run.report.alarm->code, AlarmCode::InvalidArgument);
        EXPECT_EQ(run.report.alarm->message, c.message);
        EXPECT_EQ(run.report.alarm->line, 1u);
    }
}

TEST(InterfaceSignals, AnUnwiredMachineReadsZeroAndKeepsItsOutputs) {
    auto run = runFanuc(lines({"#100=#1000", "#101=#1032", "#1101=1", "#102=#1132", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 0);
    EXPECT_EQ(run.number(101), 0);
    EXPECT_EQ(run.number(102), 2);
    for (int level : run.report.outputs) {
        EXPECT_EQ(level, 0);
    }
}

class InterfaceSignalsFolder : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ =
            std::filesystem::path(testing::TempDir()) /
            ("m350-signals-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::variant<config::MachineConfig, config::ConfigError> load(const std::string& dialect,
                                                                  const std::string& table) {
        std::ofstream(folder_ / "machine.toml")
            << "name = \"t\"\ndialect = \"" << dialect << "\"\n[interface_signals]\n"
            << table;
        return config::loadMachineFolder(folder_.string());
    }
    std::filesystem::path folder_;
};

TEST_F(InterfaceSignalsFolder, MachineTomlWiresThem) {
    auto loaded =
        load("fanuc", "UI003 = \"IN05\"\nUI001 = \"spindle_empty\"\nUO000 = \"OUT07\"\nUO131 = \"OUT21\"\n");
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded))
        << std::get<config::ConfigError>(loaded).message;
    const config::InterfaceSignals& s = std::get<config::MachineConfig>(loaded).interfaceSignals;
    EXPECT_EQ(s.inputs[3].source, Source::Input);
    EXPECT_EQ(s.inputs[3].pin, 5);
    EXPECT_EQ(s.inputs[1].source, Source::SpindleEmpty);
    EXPECT_EQ(s.outputs[0], 7);
    EXPECT_EQ(s.wideOutputs[31], 21);
}

TEST_F(InterfaceSignalsFolder, WhatCannotBeWiredIsALoadErrorAtItsPlace) {
    struct Case {
        const char* table;
        const char* where;
        const char* message;
    };
    for (Case c :
         {Case{"UI016 = \"IN05\"\n", ":4:1",
               "[interface_signals] UI016: the interface inputs run from UI000 to "
               "UI015 (#1000-#1015)"},
          Case{"UI000 = \"IN25\"\n", ":4:9",
               "[interface_signals] UI000 = \"IN25\": an input is IN01-IN24, "
               "\"commanded_tool_in_spindle\", \"spindle_empty\", \"t0_commanded\", "
               "\"tool_change_signal\" or \"new_tool_signal\""},
          Case{"UO016 = \"OUT01\"\n", ":4:1",
               "[interface_signals] UO016: the interface signals are UI000-UI015 "
               "(or UI for all of them), UO000-UO015 and UO100-UO131"},
          Case{"UO100 = \"IN01\"\n", ":4:9",
               "[interface_signals] UO100 = \"IN01\": an interface output drives "
               "OUT01-OUT21"},
          Case{
              "UI = \"spindle_load\"\nUI000 = \"IN01\"\n", ":4:6",
              "[interface_signals] UI gives all sixteen inputs the spindle load: UI000-UI015 cannot be wired "
              "too"},
          Case{"UI000 = 5\n", ":4:9",
               "[interface_signals] UI000 must be a signal's name in quotes, such as "
               "\"IN05\" or \"OUT07\""}}) {
        auto loaded = load("fanuc", c.table);
        const auto* error = std::get_if<config::ConfigError>(&loaded);
        ASSERT_NE(error, nullptr) << c.table;
        EXPECT_EQ(error->where(), (folder_ / "machine.toml").string() + c.where) << c.table;
        EXPECT_EQ(error->message, c.message);
    }
}

TEST_F(InterfaceSignalsFolder, AnM350MachineIgnoresThemWithAWarning) {
    auto loaded = load("m350", "UI000 = \"IN05\"\n");
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const auto& warnings = std::get<config::MachineConfig>(loaded).warnings;
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(
        warnings[0].find("[interface_signals] are a FANUC's (#1000-#1133): this M350 machine ignores them"),
        std::string::npos)
        << warnings[0];
}

// --- #3003 / #3004 ----------------------------------------------------------------------------

TEST(OperationControl, ValuesAreReadBackAndOutOfRangeOnesRefused) {
    auto run = runFanuc(lines({"#3003=3", "#3004=7", "#100=#3003", "#101=#3004", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_EQ(run.number(100), 3);
    EXPECT_EQ(run.number(101), 7);
    auto wrong = runFanuc(lines({"#3004=8", "M30"}));
    ASSERT_EQ(wrong.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(
        wrong.report.alarm->message,
        "#3004 = 8: it takes 0 to 7 (bit 0 no feed hold, bit 1 no feed override, bit 2 no exact stop check)");
    auto half = runFanuc(lines({"#3003=0.5", "M30"}));
    ASSERT_EQ(half.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(
        half.report.alarm->message,
        "#3003 = 0.5: it takes 0 to 3 (bit 0 no single block stop, bit 1 no wait for M, S, T completion)");
}

TEST(OperationControl, FeedOverrideIsIgnoredWhileBit1OfThe3004IsOn) {
    // 100 mm at F600 (10 mm/s): 10 s at 100 %, 20 s at the panel's 50 %
    auto timed = [](const std::string& text) {
        ProgramRun run = loadProgram(fanucMachine(), text);
        EXPECT_TRUE(run.loaded) << run.diagnostics();
        run.controller->setFeedOverride(50.0);
        run.report = run.controller->run();
        EXPECT_RUN_OK(run);
        return run.report.simTime;
    };
    const double halved = timed(lines({"G91G1X100.F600", "M30"}));
    const double locked = timed(lines({"#3004=2", "G91G1X100.F600", "#3004=0", "M30"}));
    const double back = timed(lines({"#3004=2", "#3004=0", "G91G1X100.F600", "M30"}));
    EXPECT_GT(halved, 19.5);
    EXPECT_LT(locked, 10.5);
    EXPECT_GT(locked, 9.5);
    EXPECT_NEAR(back, halved, 1e-3) << "clearing the bit gives the panel's override back";
}

TEST(OperationControl, PauseIsHeldBackUntilTheMacroAllowsFeedHoldAgain) {
    const std::string text = lines({"#3004=3", "G91G1X100.F600", "G1X20.", "#3004=0", "G1X30.", "M30"});
    ProgramRun run = loadProgram(fanucMachine(), text);
    ASSERT_TRUE(run.loaded) << run.diagnostics();
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(1.0); // 1 s into the 10 s move
    c.hold();
    EXPECT_EQ(c.runState(), controller::RunState::Running) << "feed hold is off: the run goes on";
    c.advance(30.0);
    EXPECT_EQ(c.runState(), controller::RunState::Hold) << "it holds where #3004 = 0 allows it again";
    EXPECT_NEAR(c.displayPosition()(0), 120.0, 1e-6) << "both moves done, the one after #3004 = 0 not begun";
    c.resume();
    c.advance(std::numeric_limits<double>::infinity());
    EXPECT_EQ(c.runState(), controller::RunState::Finished);
    EXPECT_NEAR(c.displayPosition()(0), 150.0, 1e-6);
}

TEST(OperationControl, WithoutTheBitPauseHoldsAtOnce) {
    ProgramRun run = loadProgram(fanucMachine(), lines({"G91G1X100.F600", "M30"}));
    ASSERT_TRUE(run.loaded);
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    c.hold();
    EXPECT_EQ(c.runState(), controller::RunState::Hold);
    EXPECT_LT(c.displayPosition()(0), 20.0);
}

TEST(OperationControl, SingleBlockDoesNotStopWhileBit0OfThe3003IsOn) {
    controller::RunSettings settings;
    settings.singleBlock = true;
    auto run = runFanuc(
        lines({"G91G1X1.F600", "G1X1.", "#3003=1", "G1X1.", "G1X1.", "#3003=0", "G1X1.", "M30"}), settings);
    EXPECT_RUN_OK(run);
    EXPECT_EQ(countMessages(run.report, "single block stop"), 3u) << "after lines 1, 2 and 7 only";
    EXPECT_EQ(countMessages(run.report, ":7): START pressed"), 1u);
    auto plain = runFanuc(lines({"G91G1X1.F600", "G1X1.", "#1=1", "G1X1.", "M30"}), settings);
    EXPECT_EQ(countMessages(plain.report, "single block stop"), 3u) << "a macro statement is no stop";
}

TEST(OperationControl, AResetClearsBoth) {
    ProgramRun run = loadProgram(fanucMachine(), lines({"#3003=1", "#3004=3", "G91G1X100.F600", "M30"}));
    ASSERT_TRUE(run.loaded);
    controller::Controller& c = *run.controller;
    ASSERT_TRUE(c.start());
    c.advance(1.0);
    EXPECT_EQ(c.operationControl().value(4), 3);
    c.reset();
    EXPECT_EQ(c.operationControl().value(3), 0);
    EXPECT_EQ(c.operationControl().value(4), 0);
}

} // namespace
