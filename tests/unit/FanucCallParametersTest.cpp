// G and M codes (and addresses) that call programs because a FANUC parameter says so: 6050-6059
// (G code -> macro O9010-O9019), 6071-6079 (M code -> subprogram O9001-O9009), 6080-6089 (M code
// -> macro O9020-O9029), 6090-6091 (address -> subprogram O9004/O9005, its value in #146/#147);
// one table with machine.toml's [codes]; inside a program a code called, codes are ordinary.
#include "RunProgram.h"

#include "core/config/CallCodeParameters.h"
#include "core/params/FanucParameters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

namespace {

using namespace m350;
using namespace m350::test;

controller::RunSettings withParameters(std::map<int, double> parameters) {
    controller::RunSettings settings;
    settings.parameters = std::move(parameters);
    return settings;
}

TEST(FanucCallParameters, AGCodeCallsItsMacroWithArgumentsAsG65Does) {
    // the mould shop's G100: every letter of argument specification I, M and T included
    auto run = runFanuc(
        lines({"#1=99.", "G100A1.B2.C3.I4.J5.K6.D7.E8.F9.H11.M13.Q17.R18.S19.T20.U21.V22.W23.X24.Y25.Z26.",
               "#101=#1", "M30", "O9010", "#100=0", "#110=1", "WHILE[#110LE26]DO1", "IF[#[#110]EQ#0]GOTO5",
               "#100=#100+#[#110]", "N5#110=#110+1", "END1", "#1=-1.", "M99"}),
        withParameters({{6050, 100}}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 1 + 2 + 3 + 4 + 5 + 6 + 7 + 8 + 9 + 11 + 13 + 17 + 18 + 19 + 20 + 21 +
                                          22 + 23 + 24 + 25 + 26);
    EXPECT_DOUBLE_EQ(run.number(101), 99) << "the macro's locals are a level of their own";
}

TEST(FanucCallParameters, TheNinthGCodeParameterCallsO9019AndLRepeats) {
    auto run = runFanuc(lines({"G966L3X2.", "M30", "O9019", "#100=#100+#24", "M99"}),
                        withParameters({{6059, 966}, {6050, 100}}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 6);
}

TEST(FanucCallParameters, AnMCodeMacroGetsArguments) {
    auto run = runFanuc(lines({"M120A5.T3.", "M30", "O9021", "#100=#1", "#101=#20", "M99"}),
                        withParameters({{6081, 120}}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 5);
    EXPECT_DOUBLE_EQ(run.number(101), 3);
}

TEST(FanucCallParameters, AnMCodeSubprogramRunsAfterTheBlockWithTheCallersLocals) {
    // the pallet changer's M61: the move of its block first, then O9003 with no arguments
    auto run = runFanuc(
        lines({"#1=7.", "G90G00X12.M61", "M30", "O9003", "#100=#1", "#101=#5041", "#102=#24", "M99"}),
        withParameters({{6073, 61}}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 7) << "no new level of locals";
    EXPECT_DOUBLE_EQ(run.number(101), 12) << "the block's move came first";
    EXPECT_TRUE(run.vacant(102)) << "X is no argument of a subprogram call";
}

TEST(FanucCallParameters, AnAddressCallsItsSubprogramWithItsValueInACommonVariable) {
    auto run = runFanuc(lines({"G90G00X5.B100.", "G00Y2.D3.", "M30", "O9004", "#100=#146", "#101=#5041",
                               "M99", "O9005", "#102=#147", "#103=#5042", "M99"}),
                        withParameters({{6090, 66}, {6091, 68}}));
    EXPECT_RUN_OK(run);
    EXPECT_DOUBLE_EQ(run.number(100), 100);
    EXPECT_DOUBLE_EQ(run.number(101), 5);
    EXPECT_DOUBLE_EQ(run.number(102), 3);
    EXPECT_DOUBLE_EQ(run.number(103), 2);
    EXPECT_DOUBLE_EQ(run.report.machine(4), 0.0) << "B called; it moved no axis";
}

TEST(FanucCallParameters, InsideAProgramACodeCalledItsCodesAreOrdinary) {
    // FANUC: a G code in a macro called by a G code is an ordinary G code (here: unknown)
    auto run = runFanuc(lines({"G100X1.", "M30", "O9010", "G100X2.", "M99"}), withParameters({{6050, 100}}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.report.alarm->line, 4u);
    EXPECT_EQ(run.report.alarm->column, 1u);
    EXPECT_EQ(run.report.alarm->message, "G100: not a G code this machine knows");
    // an M code in it goes to the PMC: O9020 does not run
    auto m = runFanuc(lines({"G100X1.", "M120", "M30", "O9010", "M120", "#100=#100+1", "M99", "O9020",
                             "#101=#101+1", "M99"}),
                      withParameters({{6050, 100}, {6080, 120}}));
    EXPECT_RUN_OK(m);
    EXPECT_DOUBLE_EQ(m.number(100), 1);
    EXPECT_DOUBLE_EQ(m.number(101), 1) << "only the main program's M120 called";
    // G65 still calls from there
    auto g65 = runFanuc(lines({"G100X1.", "M30", "O9010", "G65P5A2.", "M99", "O5", "#100=#1", "M99"}),
                        withParameters({{6050, 100}}));
    EXPECT_RUN_OK(g65);
    EXPECT_DOUBLE_EQ(g65.number(100), 2);
}

TEST(FanucCallParameters, WithoutTheParameterG100IsRefusedAtItsLineAndColumn) {
    auto run = runFanuc(lines({"G00X1.", "G100T1", "M30"}));
    ASSERT_EQ(run.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(run.alarmText(),
              "invalid_word at " + run.fileName + ":2:1: G100: not a G code this machine knows");
}

TEST(FanucCallParameters, HaasCodesAndVariablesAreRefusedAtTheirLineAndColumn) {
    auto g103 = runFanuc(lines({"G00X1.", "G103P1", "M30"}));
    ASSERT_EQ(g103.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(g103.alarmText(),
              "invalid_word at " + g103.fileName + ":2:1: G103: not a G code this machine knows");
    auto common = runFanuc(lines({"#1=2.", "#10000=#1", "M30"}));
    ASSERT_EQ(common.report.status, controller::RunStatus::Alarm);
    EXPECT_EQ(common.report.alarm->line, 2u);
    EXPECT_EQ(common.report.alarm->column, 1u);
    EXPECT_NE(common.report.alarm->message.find("10000"), std::string::npos) << common.alarmText();
}

TEST(FanucCallParameters, ASettingThatIsNoCodeIsRefused) {
    struct Case {
        int number;
        double value;
        const char* message;
    };
    for (Case c :
         {Case{6050, 100.5, "parameter 6050 = 100.5: a code number is a whole number"},
          Case{6050, 65, "parameter 6050 = 65: G65 cannot call a program (the controller itself needs it)"},
          Case{6080, 98, "parameter 6080 = 98: M98 cannot call a program (the controller itself needs it)"},
          Case{6071, 30, "parameter 6071 = 30: M30 cannot call a program (the controller itself needs it)"},
          Case{6090, 77,
               "parameter 6090 = 77: an address that calls O9004 is the ASCII code of one of "
               "A B D F H I J K Q R S T (65 A, 66 B, ...)"}}) {
        macro::CallCodes table;
        auto refused = config::addCallParameters(table, {{c.number, c.value}}, {});
        ASSERT_TRUE(refused.has_value()) << c.number << " = " << c.value;
        EXPECT_EQ(refused->message, c.message);
        EXPECT_EQ(refused->parameter, c.number);
        EXPECT_TRUE(table.empty());
    }
}

TEST(FanucCallParameters, TwoSettingsForOneCodeAreRefusedNamingBoth) {
    macro::CallCodes table;
    ASSERT_FALSE(
        table.add('M', 6, {9001, macro::CallKind::Subprogram, 0, "[codes] M6 = 9001 (machine.toml:13:1)"}));
    auto refused = config::addCallParameters(table, {{6071, 6}}, {{6071, "params.toml:5:8"}});
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->message,
              "parameter 6071 = 6 makes M6 call O9001, but [codes] M6 = 9001 (machine.toml:13:1) "
              "already makes it call O9001: keep one of them");
    macro::CallCodes two;
    refused = config::addCallParameters(two, {{6050, 100}, {6052, 100}}, {{6050, "params.toml:2:8"}});
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->parameter, 6052);
    EXPECT_EQ(refused->message, "parameter 6052 = 100 makes G100 call O9012, but parameter 6050 = 100 "
                                "(params.toml:2:8) already makes it call O9010: keep one of them");
}

// The Controller itself (the panel's path; m350-sim refuses the clash before): the machine's call
// codes stay and the message line says why, in the panel's language.
TEST(FanucCallParameters, AClashOfTheRunSettingsKeepsTheCallCodesAndSaysSo) {
    auto run = runFanuc(lines({"#100=1", "M30"}), withParameters({{6050, 100}, {6052, 100}}));
    EXPECT_RUN_OK(run);
    const std::vector<Message>& said = run.report.messageWords;
    auto kept = std::find_if(said.begin(), said.end(), [](const Message& m) { return m.id == "call_codes_kept"; });
    ASSERT_NE(kept, said.end()) << ::testing::PrintToString(run.report.messages);
    EXPECT_EQ(kept->english(), "parameter 6052 = 100 makes G100 call O9012, but parameter 6050 = 100 (--param 6050) "
                               "already makes it call O9010: keep one of them (the machine's call codes are kept)");
    EXPECT_EQ(kept->in(MessageLanguage::Chinese),
              "参数6052 = 100使G100调用O9012，但参数6050 = 100 (--param 6050)已使其调用O9010：请只保留其中一个"
              "（机床的调用代码保持不变）");
}

TEST(FanucCallParameters, ACallParameterIsSimulatedAndNoLongerWarned) {
    for (int number : {6050, 6059, 6071, 6079, 6080, 6089, 6090, 6091}) {
        EXPECT_FALSE(params::unreadFanucParameter(number).has_value()) << number;
    }
    EXPECT_TRUE(params::unreadFanucParameter(6070).has_value());
    EXPECT_TRUE(params::unreadFanucParameter(6092).has_value());
    EXPECT_EQ(params::refusedFanucParameter(6050, -100), "parameter 6050 must be from 0 to 9999");
    EXPECT_EQ(params::refusedFanucParameter(6090, 91), "parameter 6090 must be from 0 to 90");
    EXPECT_EQ(params::refusedFanucParameter(6090, 91)->in(MessageLanguage::Chinese), "参数6090须在0到90之间");
}

class CallParameterFolder : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ =
            std::filesystem::path(testing::TempDir()) /
            ("m350-callparams-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(folder_);
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    void write(const std::string& name, const std::string& text) { std::ofstream(folder_ / name) << text; }
    std::filesystem::path folder_;
};

TEST_F(CallParameterFolder, ParamsTomlFeedsTheTableBesideCodes) {
    write("machine.toml", "name = \"t\"\ndialect = \"fanuc\"\n[codes]\nM6 = 9001\n");
    write("params.toml", "[params]\n6050 = 100\n6090 = 66\n");
    auto loaded = config::loadMachineFolder(folder_.string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const auto& machine = std::get<config::MachineConfig>(loaded);
    ASSERT_NE(machine.callCodes.find('M', 6), nullptr);
    EXPECT_EQ(machine.callCodes.find('M', 6)->kind, macro::CallKind::Subprogram);
    ASSERT_NE(machine.callCodes.find('G', 100), nullptr);
    EXPECT_EQ(machine.callCodes.find('G', 100)->program, 9010);
    EXPECT_EQ(machine.callCodes.find('G', 100)->kind, macro::CallKind::Macro);
    ASSERT_NE(machine.callCodes.address('B'), nullptr);
    EXPECT_EQ(machine.callCodes.address('B')->valueVariable, 146);
    for (const std::string& warning : machine.warnings) {
        EXPECT_EQ(warning.find("not simulated"), std::string::npos) << warning;
    }
}

TEST_F(CallParameterFolder, AClashWithCodesIsALoadErrorAtTheParameter) {
    write("machine.toml", "name = \"t\"\ndialect = \"fanuc\"\n[codes]\nM6 = 9001\n");
    write("params.toml", "[params]\n61 = 3000\n6071 = 6\n");
    auto loaded = config::loadMachineFolder(folder_.string());
    const auto* error = std::get_if<config::ConfigError>(&loaded);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->where(), (folder_ / "params.toml").string() + ":3:8");
    EXPECT_EQ(error->message, "parameter 6071 = 6 makes M6 call O9001, but [codes] M6 = 9001 (" +
                                  (folder_ / "machine.toml").string() +
                                  ":4:1) already makes it call O9001: keep one "
                                  "of them");
}

} // namespace
