// SpindleToolGuard on its own: the length warning once per tool and only where the M350's fixed
// setter makes a length necessary, the target a stop in a change leaves in doubt (#1504 on the
// M350, the last T word on a FANUC), one doubt per stop, and which words the doubt refuses.
#include "RunProgram.h"

#include "core/controller/SpindleToolGuard.h"
#include "core/interp/ModalInterpreter.h"
#include "core/interp/WorkOffsets.h"
#include "core/machine/ScanMachine.h"
#include "core/machine/SimulatedMachine.h"
#include "core/macro/Executor.h"
#include "core/tools/ToolData.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>

namespace {

using namespace m350;
using controller::SpindleToolGuard;

// What the guard reads, as a Controller holds it: a machine folder, its magazine driver (built),
// no program running.
struct GuardBench {
    explicit GuardBench(config::MachineConfig machineConfig) : config(std::move(machineConfig)) { magazine.build(); }

    macro::EvaluatedBlock block(std::initializer_list<macro::WordValue> words) const {
        macro::EvaluatedBlock out;
        for (const macro::WordValue& w : words) {
            out.add(w.letter, w.value, w.column);
        }
        return out;
    }

    config::MachineConfig config;
    controller::RunSettings settings;
    machine::SimulatedMachine machine;
    machine::ScanMachine scan{machine};
    interp::WorkOffsets offsets;
    tools::ToolData tools{*config.dialect, config.parameters, config.toolTable};
    interp::ModalInterpreter interp{*config.dialect, config.parameters, offsets, tools, scan};
    int pmcTool = 0;
    std::map<int, controller::TraceSource> inputs;
    controller::MagazineDriver magazine{
        {config, settings, machine, interp, pmcTool, inputs, [] { return controller::TraceSource{}; }}};
    std::unique_ptr<macro::Executor> executor;
    macro::Value target = macro::Value::empty(); // #1504
    SpindleToolGuard guard{{*config.dialect, config.parameters, magazine, executor, [this](int number) {
                                return number == 1504 ? target : macro::Value::empty();
                            }}};
};

int zParameter(const GuardBench& bench, int tool) { return *tools::m350ZParameter(tool, bench.config.parameters); }

TEST(SpindleToolGuard, WarnsOfAToolWithNoLengthOncePerToolWhenTheFixedSetterIsOn) {
    GuardBench bench(test::bundledMachine("m350-linear16"));
    bench.config.parameters.set(param::kFixedSetterValid, 1);
    bench.config.parameters.set(zParameter(bench, 3), 0.0);
    bench.config.parameters.set(zParameter(bench, 4), 0.0);
    bench.config.parameters.set(zParameter(bench, 5), -120.5);

    std::optional<Alarm> first = bench.guard.toolTurns(3, {"main.nc", 12});
    ASSERT_TRUE(first);
    EXPECT_EQ(first->messageId, "tool_length_unset");
    EXPECT_EQ(first->messageArguments, (std::vector<std::string>{"3", std::to_string(zParameter(bench, 3))}));
    EXPECT_EQ(first->file, "main.nc");
    EXPECT_EQ(first->line, 12u);
    EXPECT_TRUE(bench.guard.lengthLookedAt(3));
    EXPECT_FALSE(bench.guard.lengthLookedAt(4));

    EXPECT_FALSE(bench.guard.toolTurns(5, {})) << "T5 has its length";
    EXPECT_FALSE(bench.guard.toolTurns(3, {})) << "T3 was warned of already";
    EXPECT_TRUE(bench.guard.toolTurns(4, {})) << "each tool once";
    EXPECT_FALSE(bench.guard.toolTurns(0, {})) << "an empty spindle has no length";
}

TEST(SpindleToolGuard, ALengthOfZeroIsNoMistakeWithoutTheFixedSetterNorOnAFanuc) {
    GuardBench m350(test::bundledMachine("m350-linear16"));
    m350.config.parameters.set(param::kFixedSetterValid, 0);
    m350.config.parameters.set(zParameter(m350, 3), 0.0);
    EXPECT_FALSE(m350.guard.toolTurns(3, {}));

    GuardBench fanuc(test::fanucMachine());
    fanuc.config.parameters.set(param::kFixedSetterValid, 1);
    EXPECT_FALSE(fanuc.guard.toolTurns(3, {}));
}

TEST(SpindleToolGuard, AStopInAChangeDoubtsTheM350sTargetOnceUntilTheOperatorConfirms) {
    GuardBench bench(test::bundledMachine("m350-linear16"));
    bench.config.parameters.set(param::kCurrentTool, 1);
    bench.target = macro::Value::of(2);

    std::optional<Alarm> notice = bench.guard.stoppedInChange(0);
    ASSERT_TRUE(notice);
    EXPECT_EQ(notice->messageId, "tool_unsure");
    EXPECT_EQ(notice->messageArguments, (std::vector<std::string>{"2", "1"}));
    EXPECT_FALSE(bench.guard.stoppedInChange(0)) << "the E-stop, then its RESET: one stop, one doubt";

    bench.guard.confirmed();
    EXPECT_FALSE(bench.guard.doubt().doubt());
    bench.target = macro::Value::empty();
    notice = bench.guard.stoppedInChange(0);
    ASSERT_TRUE(notice);
    EXPECT_EQ(notice->messageArguments, (std::vector<std::string>{"0", "1"})) << "no #1504: no target known";
}

TEST(SpindleToolGuard, AFanucsStoppedChangeWasFetchingTheLastTWordWithThePmcsToolOnRecord) {
    GuardBench bench(test::fanucMachine());
    bench.guard.checkBlock(bench.block({{'T', 7.0, 1}}));
    bench.guard.checkBlock(bench.block({{'G', 0.0, 1}, {'X', 5.0, 4}}));
    EXPECT_EQ(bench.guard.lastToolWord(), 7);

    std::optional<Alarm> notice = bench.guard.stoppedInChange(4);
    ASSERT_TRUE(notice);
    EXPECT_EQ(notice->messageArguments, (std::vector<std::string>{"7", "4"}));
}

TEST(SpindleToolGuard, InDoubtTheNextTIsRefusedAtItsWordButAMacrosTArgumentIsNot) {
    GuardBench bench(test::bundledMachine("m350-linear16"));
    ASSERT_NE(bench.magazine.device(), nullptr);
    bench.target = macro::Value::of(2);
    bench.guard.checkBlock(bench.block({{'T', 3.0, 1}})); // no doubt yet
    ASSERT_TRUE(bench.guard.stoppedInChange(0));

    try {
        bench.guard.checkBlock(bench.block({{'M', 5.0, 1}, {'T', 3.0, 4}}));
        FAIL() << "T3 was taken in doubt";
    } catch (const macro::MacroError& error) {
        EXPECT_EQ(error.messageId, "tool_unsure_refused");
        EXPECT_EQ(error.messageArguments, (std::vector<std::string>{"2"}));
        EXPECT_EQ(error.column, 4u);
    }
    EXPECT_NO_THROW(bench.guard.checkBlock(bench.block({{'G', 65.0, 1}, {'P', 9000.0, 5}, {'T', 3.0, 11}})));
    EXPECT_NO_THROW(bench.guard.checkBlock(bench.block({{'G', 1.0, 1}, {'X', 3.0, 4}})));
}

} // namespace
