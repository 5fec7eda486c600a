// Hook files through the controller API: the table, loading and running a hook as the panel's
// keys do, the hooks the controller runs itself (pause.nc, error.nc, ALL_T.nc for M101,
// slibuser.nc), the built-in O501 homing and the K keys. Every machine folder is a copy of the
// bundled default machine with hook files the test writes.
#include "RunProgram.h"

#include "core/config/HookFiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <limits>
#include <set>

namespace {

using namespace m350;
using namespace m350::test;
using config::Hook;
using controller::Controller;
namespace fs = std::filesystem;

class HookMachine : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::path(::testing::TempDir()) / (std::string("m350_hooks_") + info->name());
        fs::remove_all(folder_);
        fs::copy(config::bundledMachinesDirectory() + "/" + config::kDefaultMachine, folder_, fs::copy_options::recursive);
    }
    void TearDown() override { fs::remove_all(folder_); }

    void write(const std::string& name, const std::string& text) {
        std::ofstream out(folder_ / name, std::ios::binary | std::ios::trunc);
        out << text;
    }
    config::MachineConfig machine() {
        auto loaded = config::loadMachineFolder(folder_.string());
        if (auto* error = std::get_if<config::ConfigError>(&loaded)) {
            ADD_FAILURE() << error->file << ": " << error->message;
            return m350Machine();
        }
        return std::get<config::MachineConfig>(std::move(loaded));
    }
    static controller::RunSettings unhomed() {
        controller::RunSettings s;
        s.homed = false;
        return s;
    }
    static std::string diagnosticsOf(const Controller& c) {
        std::string out;
        for (const gcode::Diagnostic& d : c.diagnostics()) {
            out += gcode::formatDiagnostic(d) + "\n";
        }
        return out;
    }

    fs::path folder_;
};

TEST(HookTable, NamesAndFilesAreUniqueAndFoundInAnyCase) {
    std::set<std::string_view> names, files;
    for (const config::HookFile& hook : config::hookFiles()) {
        EXPECT_TRUE(names.insert(hook.name).second) << hook.name;
        EXPECT_TRUE(files.insert(hook.fileName).second) << hook.fileName;
        EXPECT_EQ(&config::hookFile(hook.hook), &hook);
    }
    ASSERT_NE(config::findHook("FNDZERO.nc"), nullptr);
    EXPECT_EQ(config::findHook("FNDZERO.nc")->hook, Hook::HomeAll);
    EXPECT_EQ(config::findHook("key-3")->fileName, "key-3.nc");
    EXPECT_EQ(config::findHook("fndx")->hook, Hook::HomeX);
    EXPECT_EQ(config::findHook("nosuchhook"), nullptr);
    EXPECT_EQ(config::homeAxisHook(2), Hook::HomeZ);
    EXPECT_EQ(config::absoluteAxisHook(4), Hook::AbsB);
    EXPECT_EQ(config::userKeyHook(7), Hook::Key7);
    EXPECT_FALSE(config::userKeyHook(8));
    EXPECT_EQ(config::hookFile(*config::externKeyHook(2)).fileName, "extnc1-1.nc");
    EXPECT_EQ(config::mCodeKeyHook(19), Hook::M19);
    EXPECT_FALSE(config::mCodeKeyHook(6));
    EXPECT_EQ(config::runnableHookNames().find("slibuser"), std::string::npos);
}

// The dual-Y gantry owner's fndzero.nc: Z, X and Y home through the built-in O501, then A takes
// Y's machine position and is marked homed.
TEST_F(HookMachine, DualYGantryFndzeroLeavesFourAxesHomedWithAEqualToY) {
    write("fndzero.nc", lines({"M98P501X2", "M98P501X0", "M98P501X1", "#883=#881", "#1518=1", "M30"}));
    auto cfg = machine();
    cfg.parameters.set(123, 12.5);                         // Y after homing
    cfg.parameters.set(param::kHomeBeforeProcessing, 1); // a hook still runs unhomed
    Controller c(std::move(cfg), unhomed());
    ASSERT_TRUE(c.loadMdi({"G91 G00 A30", "G90"}));
    ASSERT_EQ(c.run().status, controller::RunStatus::Ok);
    ASSERT_DOUBLE_EQ(c.status().report().machine(3), 30.0);
    ASSERT_TRUE(c.hasHook(Hook::HomeAll));
    ASSERT_TRUE(c.loadHook(Hook::HomeAll)) << diagnosticsOf(c);
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    for (int axis = 0; axis < 4; ++axis) {
        EXPECT_TRUE(c.homing().homed(axis)) << axis;
    }
    EXPECT_DOUBLE_EQ(r.machine(1), 12.5);
    EXPECT_DOUBLE_EQ(r.machine(3), r.machine(1));
    EXPECT_DOUBLE_EQ(c.variable(883).number, 12.5);
}

TEST_F(HookMachine, WritingAMachinePositionUnhomesTheAxisWithoutMoving) {
    Controller c(machine(), {});
    ASSERT_TRUE(c.homing().homed(0));
    double before = c.status().report().simTime;
    ASSERT_TRUE(c.loadMdi({"#880=7.5"}));
    controller::RunReport r = c.run();
    EXPECT_DOUBLE_EQ(r.machine(0), 7.5);
    EXPECT_FALSE(c.homing().homed(0));
    EXPECT_LT(r.simTime - before, 0.01);
}

TEST_F(HookMachine, BuiltInHomingNeedsAnAxisAndGivesWayToALibraryO501) {
    Controller c(machine(), unhomed());
    ASSERT_TRUE(c.loadMdi({"M98 P501 X7"}));
    controller::RunReport bad = c.run();
    ASSERT_EQ(bad.status, controller::RunStatus::Alarm);
    EXPECT_EQ(bad.alarm->code, AlarmCode::InvalidArgument);
    EXPECT_EQ(bad.alarm->column, 1u);

    ASSERT_TRUE(c.loadMdi({"M98 P501 X2"}));
    EXPECT_TRUE(c.diagnostics().empty()) << diagnosticsOf(c); // no "no O501" finding: it is built in
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_TRUE(c.homing().homed(2));

    // the user's own O501 wins
    std::string program = writeTempFile(lines({"M98 P501 X0", "M30", "O501", "#100=[#1+41]", "M99"}));
    Controller own(machine(), unhomed());
    ASSERT_TRUE(own.loadFile(program)) << diagnosticsOf(own);
    EXPECT_TRUE(own.diagnostics().empty()) << diagnosticsOf(own);
    EXPECT_EQ(own.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(own.variable(100).number, 41);
    EXPECT_FALSE(own.homing().homed(0));
}

TEST_F(HookMachine, TNcGetsTheTargetToolInVariable1504) {
    write("T.nc", lines({"T#1504"}));
    Controller c(machine(), {});
    ASSERT_TRUE(c.loadHook(Hook::ToolWord, {{1504, 3}})) << diagnosticsOf(c);
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Ok) << (r.alarm ? r.alarm->message : "");
    EXPECT_EQ(r.tool, 3);
    EXPECT_EQ(c.loadedHook(), Hook::ToolWord);
}

TEST_F(HookMachine, AKeyWithoutItsHookRunsTheBuiltInLines) {
    Controller c(machine(), {});
    ASSERT_FALSE(c.hasHook(Hook::M8));
    ASSERT_TRUE(c.loadHookOrMdi(Hook::M8, {{100, 4}}, {"#101=[#100*2]"}));
    EXPECT_FALSE(c.loadedHook());
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(101).number, 8);

    write("M8.nc", lines({"#101=[#100*3]"}));
    ASSERT_TRUE(c.loadHookOrMdi(Hook::M8, {{100, 4}}, {"#101=[#100*2]"}));
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(101).number, 12);
}

TEST_F(HookMachine, AMissingHookIsRefusedNamingItsFile) {
    Controller c(machine(), {});
    EXPECT_FALSE(c.loadHook(Hook::PowerOn));
    ASSERT_EQ(c.diagnostics().size(), 1u);
    EXPECT_NE(c.diagnostics()[0].message.find("has no sysstart.nc (power-on, before the boot homing prompt)"),
              std::string::npos)
        << diagnosticsOf(c);
    // the zh_CN panel says it by its id, with what runs the hook in Chinese
    const gcode::Diagnostic& d = c.diagnostics()[0];
    EXPECT_EQ(d.messageId, "hook_missing");
    const std::string chinese = messageText(d.messageId, d.messageArguments, MessageLanguage::Chinese);
    EXPECT_NE(chinese.find("中没有sysstart.nc（开机时，回零提示之前）"), std::string::npos) << chinese;
    EXPECT_FALSE(c.start());
}

TEST_F(HookMachine, AHookFoundInAnotherCaseRuns) {
    write("KEY-3.NC", lines({"#100=3"}));
    Controller c(machine(), {});
    ASSERT_TRUE(c.loadHook(Hook::Key3)) << diagnosticsOf(c);
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 3);
}

TEST_F(HookMachine, AnAlarmInAHookNamesTheHookFileLineAndColumn) {
    write("probe.nc", lines({"#100=1", "#101=#100/0"}));
    Controller c(machine(), {});
    ASSERT_TRUE(c.loadHook(Hook::Probe));
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.alarm->file, "probe.nc");
    EXPECT_EQ(r.alarm->line, 2u);
    EXPECT_GT(r.alarm->column, 0u);
}

TEST_F(HookMachine, PauseNcRunsWhenARunHoldsAndStartReturnsFirst) {
    write("pause.nc", lines({"#100=[#100+1]", "G91 G00 Z5", "G90"}));
    Controller c(machine(), {});
    std::string program = writeTempFile(lines({"G90 G53 G01 X100 F600", "M30"}));
    ASSERT_TRUE(c.loadFile(program));
    ASSERT_TRUE(c.start());
    c.advance(2.0);
    c.hold();
    ASSERT_EQ(c.runState(), Controller::RunState::Hold);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 1);
    controller::RunReport held = c.status().report();
    EXPECT_NEAR(held.machine(2), 5.0, 1e-9);
    double stoppedX = held.machine(0);
    EXPECT_GT(stoppedX, 5.0);
    EXPECT_LT(stoppedX, 100.0);
    c.resume();
    while (c.advance(std::numeric_limits<double>::infinity()) == Controller::RunState::Running) {
    }
    controller::RunReport done = c.status().report();
    EXPECT_EQ(done.status, controller::RunStatus::Ok);
    EXPECT_NEAR(done.machine(0), 100.0, 1e-9);
    EXPECT_NEAR(done.machine(2), 0.0, 1e-9); // back down to where the hold stopped it
}

TEST_F(HookMachine, PauseNcRunsAtM00Too) {
    write("pause.nc", lines({"#100=[#100+1]"}));
    Controller c(machine(), {});
    std::string program = writeTempFile(lines({"M00", "M00", "M30"}));
    ASSERT_TRUE(c.loadFile(program));
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 2);
}

TEST_F(HookMachine, ErrorNcRunsAfterAnAlarmAndItsOwnAlarmIsOnlyAMessage) {
    write("error.nc", lines({"#100=9", "#1560=1", "#102=1/0"}));
    Controller c(machine(), {});
    std::string program = writeTempFile(lines({"#101=1/0"}));
    ASSERT_TRUE(c.loadFile(program));
    controller::RunReport r = c.run();
    ASSERT_EQ(r.status, controller::RunStatus::Alarm);
    EXPECT_EQ(r.alarm->line, 1u); // the program's alarm stands
    EXPECT_NE(r.alarm->file, "error.nc");
    EXPECT_DOUBLE_EQ(c.variable(100).number, 9);
    EXPECT_EQ(r.outputs[8], 1); // OUT09, which error.nc switched on after the safe state
    bool said = false;
    for (const std::string& m : r.messages) {
        said |= m.find("error.nc:3:") != std::string::npos;
    }
    EXPECT_TRUE(said);
}

TEST_F(HookMachine, EmergencyStopDoesNotRunErrorNc) {
    write("error.nc", lines({"#100=9"}));
    Controller c(machine(), {});
    c.emergencyStop();
    EXPECT_DOUBLE_EQ(c.variable(100).number, 0);
}

TEST_F(HookMachine, M101RunsAllTNc) {
    write("ALL_T.nc", lines({"#100=[#100+1]", "M99"}));
    Controller c(machine(), {});
    std::string program = writeTempFile(lines({"M101", "M101", "M30"}));
    ASSERT_TRUE(c.loadFile(program)) << diagnosticsOf(c);
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 2);
}

TEST_F(HookMachine, SlibuserNcHandlesG100ToG199) {
    write("slibuser.nc", lines({"O9150", "#100=[#0+1]", "M99"}));
    auto cfg = machine();
    Controller c(std::move(cfg), {});
    ASSERT_TRUE(c.loadMdi({"G150 X4"})) << diagnosticsOf(c);
    EXPECT_EQ(c.run().status, controller::RunStatus::Ok);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 5);
}

TEST_F(HookMachine, UserKeysRunTheirHookSwitchAnOutputOrNameAPanelKey) {
    write("key-1.nc", lines({"#100=11"}));
    auto cfg = machine();
    cfg.parameters.set(210, 0);    // K1 runs key-1.nc (the factory value 1 switches OUT01)
    cfg.parameters.set(213, 0);    // K4 runs key-4.nc, which the folder has not
    cfg.parameters.set(211, 9);    // K2 switches OUT09
    cfg.parameters.set(212, 1323); // K3 is the Probe key
    cfg.parameters.set(214, 500);  // K5: nothing
    Controller c(std::move(cfg), {});
    controller::KeyPress k1 = c.operatorPanel().pressUserKey(1);
    ASSERT_EQ(k1.kind, controller::KeyPress::Kind::Hook) << k1.why;
    EXPECT_EQ(c.loadedHook(), Hook::Key1);
    c.run();
    EXPECT_DOUBLE_EQ(c.variable(100).number, 11);

    EXPECT_EQ(c.operatorPanel().pressUserKey(2).kind, controller::KeyPress::Kind::Output);
    EXPECT_EQ(c.status().report().outputs[8], 1);
    c.operatorPanel().pressUserKey(2);
    EXPECT_EQ(c.status().report().outputs[8], 0);

    controller::KeyPress k3 = c.operatorPanel().pressUserKey(3);
    EXPECT_EQ(k3.kind, controller::KeyPress::Kind::PanelKey);
    EXPECT_EQ(k3.value, 1323);
    controller::KeyPress k4 = c.operatorPanel().pressUserKey(4);
    EXPECT_EQ(k4.kind, controller::KeyPress::Kind::Refused);
    EXPECT_NE(k4.why.english().find("key-4.nc"), std::string::npos) << k4.why;
    controller::KeyPress k5 = c.operatorPanel().pressUserKey(5);
    EXPECT_EQ(k5.kind, controller::KeyPress::Kind::Refused);
    EXPECT_NE(k5.why.english().find("parameter 214 = 500"), std::string::npos) << k5.why;
    // the panel says a refused key in its language (KeyPress::why is said by id)
    EXPECT_EQ(k5.why.id, "key_no_function");
    EXPECT_NE(k5.why.in(MessageLanguage::Chinese).find("K5：参数214 = 500不是按键功能"), std::string::npos)
        << k5.why.in(MessageLanguage::Chinese);
    EXPECT_EQ(c.operatorPanel().pressUserKey(8).why.in(MessageLanguage::Chinese), "K8：面板只有K1-K7");
    EXPECT_EQ(c.operatorPanel().pressExternKey(9).why.in(MessageLanguage::Chinese), "外部按键9：只有按键1-6");
}

TEST_F(HookMachine, ExternalKeysAndFunctionKeysRunTheirHooks) {
    write("extnc1-1.nc", lines({"#100=22"}));
    write("ext_button.nc", lines({"#101=#1996"}));
    Controller c(machine(), {});
    ASSERT_EQ(c.operatorPanel().pressExternKey(2).kind, controller::KeyPress::Kind::Hook);
    c.run();
    EXPECT_DOUBLE_EQ(c.variable(100).number, 22);
    ASSERT_TRUE(c.operatorPanel().loadFunctionKey(3)) << diagnosticsOf(c);
    c.run();
    EXPECT_DOUBLE_EQ(c.variable(101).number, 252);
    EXPECT_FALSE(c.operatorPanel().loadFunctionKey(15));
}

TEST_F(HookMachine, NoHookLoadsWhileAProgramRuns) {
    write("key-1.nc", lines({"#100=1"}));
    Controller c(machine(), {});
    ASSERT_TRUE(c.loadMdi({"G91 G01 X50 F600"}));
    ASSERT_TRUE(c.start());
    c.advance(0.5);
    EXPECT_FALSE(c.loadHook(Hook::Key1));
    EXPECT_NE(diagnosticsOf(c).find("a program is running"), std::string::npos);
    EXPECT_EQ(c.advance(std::numeric_limits<double>::infinity()), Controller::RunState::Finished);
    EXPECT_DOUBLE_EQ(c.variable(100).number, 0);
}

} // namespace

namespace {

// Our bundled machine folders ship their own hooks (fndzero.nc, T.nc, M3.nc, probe.nc ...): each
// runs to its end on its machine as the panel would run it.
TEST(BundledHooks, EveryShippedHookRunsOnItsMachine) {
    const std::map<Hook, std::map<int, double>> panelSets{
        {Hook::ToolWord, {{1504, 2}}}, {Hook::Probe, {{1502, 2}}}, {Hook::MultiProbe, {{1970, 2}, {1971, 3}}}};
    int ran = 0;
    for (const auto& entry : fs::directory_iterator(config::bundledMachinesDirectory())) {
        const std::string name = entry.path().filename().string();
        for (const config::HookFile& file : config::hookFiles()) {
            if (!file.runnable || !config::hookPath(entry.path().string(), file.hook)) {
                continue;
            }
            controller::RunSettings settings;
            settings.homed = !(file.hook >= Hook::HomeAll && file.hook <= Hook::HomeB);
            Controller c(bundledMachine(name), settings);
            auto set = panelSets.find(file.hook);
            ASSERT_TRUE(c.loadHook(file.hook, set == panelSets.end() ? std::map<int, double>{} : set->second))
                << name << "/" << file.fileName;
            controller::RunReport r = c.run();
            EXPECT_EQ(r.status, controller::RunStatus::Ok)
                << name << "/" << file.fileName << ": " << (r.alarm ? r.alarm->message : "");
            ++ran;
        }
    }
    EXPECT_GE(ran, 37); // 6 M350 machines x T, gotozero, M3-M5; the default one also homes, probes, parks
}

} // namespace
