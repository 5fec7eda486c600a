// FANUC shop programs as they run on the control, through m350-sim as a user runs them: a probing
// package's compact G65 calls, the system variables a 0i has for automatic operation and the PMC's
// interface signals, G and M codes that call macros by parameter, and the refusals programs for
// other controls (Haas, Brother) meet on the FANUC machines.
#include "tests/cli/CliFixture.h"

#include <gtest/gtest.h>

namespace m350::clitest {

namespace {

// The probing package's call as the shop wrote it: every argument from a variable, no spaces, the
// last one `E2.` right after `Y#32`.
const char* const kProbeCall =
    "%\nO1000(PROBE WEB)\n#7=6.#15=150.#11=1.#13=0.5\n#19=3.#20=12.#23=4.#31=25.#32=-18.5\n"
    "G65P9730D#7F#15H#11M#13S#19T#20W#23X#31Y#32E2.\nM30\n"
    "O9730\n#100=#24\n#101=#25\n#102=#8\n#103=#7+#9+#11+#13+#19+#20+#23\nM99\n%\n";

} // namespace

TEST_F(CliTest, AVariableFollowedByEIsTwoWordsInAProbingCall) {
    write("probe.nc", kProbeCall);
    ProcessResult check = sim({"check", "probe.nc", "--dialect", "fanuc"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    EXPECT_EQ(output(check).value("status", ""), "ok") << check.out;
    ProcessResult r = sim({"run", "probe.nc", "--dialect", "fanuc", "--print", "100,101,102,103"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"], json({{"100", 25.0}, {"101", -18.5}, {"102", 2.0}, {"103", 176.5}})) << r.out;
}

TEST_F(CliTest, AVariableFollowedByEIsTwoWordsOnTheM350Too) {
    write("move.nc", "#31=1.#32=2.\nG90G1X#31Y#32E2.F100\nM30\n");
    ProcessResult check = sim({"check", "move.nc"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    // issue 26: the M350 has no address E, so the word E2. (at its own column) is an alarm, not
    // dropped in silence
    ProcessResult r = sim({"run", "move.nc"});
    EXPECT_EQ(r.exitStatus, kExitAlarm) << r.err;
    json j = output(r);
    EXPECT_EQ(j["alarm"].value("message_id", ""), "improper_address") << r.out;
    EXPECT_EQ(j["alarm"].value("column", 0), 14) << r.out; // the E of `Y#32E2.`
    EXPECT_NE(r.err.find("E2: the M350 has no address E"), std::string::npos) << r.err;
}

TEST_F(CliTest, ExponentNotationStaysRefusedAtItsLineAndColumn) {
    for (const char* dialect : {"m350", "fanuc"}) {
        write("exp.nc", "#1=2.\nG1X#1Y1.E2\nM30\n");
        ProcessResult r = sim({"check", "exp.nc", "--dialect", dialect});
        EXPECT_EQ(r.exitStatus, kExitError) << dialect;
        EXPECT_NE(r.err.find("exp.nc:2:7: '1.E2' is not a G-code number"), std::string::npos)
            << dialect << r.err;
    }
}

namespace {

const char* const kFanucMill = "name = \"shop 0i\"\ndialect = \"fanuc\"\n";

// The mould shop's facing macro, called as G100 by the owner's parameter 6050 = 100: arguments as
// G65 passes them, and an M code of the pallet changer (6071 = 60 -> O9001) after its block's move.
const char* const kMouldShop = "O2000\nG90G00X0.Y0.\nG100X40.Y30.Z-2.F800.\nG00X5.M60\nM30\n"
                               "O9010(FACE)\n#100=#24*#25\n#101=#26\n#102=#9\nM99\n"
                               "O9001(PALLET)\n#103=#5041\n#104=#24\nM99\n";

} // namespace

TEST_F(CliTest, GCodesAndMCodesCallTheirProgramsOnceTheParametersSaySo) {
    write("shop/machine.toml", kFanucMill);
    write("shop/params.toml", "[params]\n61 = 3000\n6050 = 100\n6071 = 60\n");
    write("mould.nc", kMouldShop);
    ProcessResult check = sim({"check", "mould.nc", "--config", "shop"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    EXPECT_EQ(check.err.find("not simulated"), std::string::npos) << "a live parameter is not warned:\n"
                                                                  << check.err;
    ProcessResult r = sim({"run", "mould.nc", "--config", "shop", "--print", "100,101,102,103,104"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"],
              json({{"100", 1200.0}, {"101", -2.0}, {"102", 800.0}, {"103", 5.0}, {"104", nullptr}}))
        << r.out;
}

TEST_F(CliTest, AMacroCallCodesEAfterANumberIsItsArgument) {
    write("shop/machine.toml", kFanucMill);
    write("shop/params.toml", "[params]\n6050 = 100\n");
    write("e.nc", "G100X1.E2.\nM30\nO9010\n#100=#8\nM99\n");
    ProcessResult check = sim({"check", "e.nc", "--config", "shop"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult r = sim({"run", "e.nc", "--config", "shop", "--print", "100"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(output(r)["vars"].value("100", json()), 2.0) << r.out;
    // without the call the same line is an exponent
    ProcessResult plain = sim({"check", "e.nc", "--dialect", "fanuc"});
    EXPECT_EQ(plain.exitStatus, kExitError);
    EXPECT_NE(plain.err.find("e.nc:1:6: '1.E2.' is not a G-code number"), std::string::npos) << plain.err;
}

TEST_F(CliTest, WithoutTheParameterG100IsRefusedAtItsLineAndColumn) {
    write("shop/machine.toml", kFanucMill);
    write("mould.nc", kMouldShop);
    ProcessResult check = sim({"check", "mould.nc", "--config", "shop"});
    EXPECT_EQ(check.exitStatus, kExitError);
    EXPECT_NE(check.err.find("mould.nc:3:1: G100: not a G code this machine knows"), std::string::npos)
        << check.err;
    ProcessResult r = sim({"run", "mould.nc", "--config", "shop"});
    EXPECT_EQ(r.exitStatus, kExitAlarm);
    EXPECT_NE(r.err.find("mould.nc:3:1: alarm: G100: not a G code this machine knows"), std::string::npos)
        << r.err;
    // --param makes it a call for this run
    ProcessResult set = sim({"run", "mould.nc", "--config", "shop", "--param", "6050=100", "--param",
                             "6071=60", "--print", "100"});
    EXPECT_EQ(set.exitStatus, kExitOk) << set.err;
    EXPECT_EQ(output(set)["vars"].value("100", json()), 1200.0) << set.out;
}

TEST_F(CliTest, InsideAMacroACodeCalledItsCallingCodesAreOrdinary) {
    write("shop/machine.toml", kFanucMill);
    write("shop/params.toml", "[params]\n6050 = 100\n");
    write("nest.nc", "G100X1.\nM30\nO9010\nG100X2.\nM99\n");
    ProcessResult r = sim({"run", "nest.nc", "--config", "shop"});
    EXPECT_EQ(r.exitStatus, kExitAlarm);
    EXPECT_NE(r.err.find("nest.nc:4:1: alarm: G100: not a G code this machine knows"), std::string::npos)
        << r.err;
}

TEST_F(CliTest, AParameterAndCodesCallingOneCodeAreALoadErrorNamingBoth) {
    write("shop/machine.toml", std::string(kFanucMill) + "[codes]\nM6 = 9001\n");
    write("shop/params.toml", "[params]\n61 = 3000\n6071 = 6\n");
    write("t.nc", "M30\n");
    ProcessResult r = sim({"run", "t.nc", "--config", "shop"});
    EXPECT_EQ(r.exitStatus, kExitError);
    EXPECT_NE(r.err.find(
                  "shop/params.toml:3:8: parameter 6071 = 6 makes M6 call O9001, but [codes] M6 = 9001 (shop/"
                  "machine.toml:4:1) already makes it call O9001: keep one of them"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(output(r)["alarm"].value("code", ""), "config_error");
    // the same clash from the command line is a usage error
    write("shop/params.toml", "[params]\n61 = 3000\n");
    ProcessResult usage = sim({"run", "t.nc", "--config", "shop", "--param", "6071=6"});
    EXPECT_EQ(usage.exitStatus, kExitUsage);
    EXPECT_NE(usage.err.find("--param 6071: parameter 6071 = 6 makes M6 call O9001, but [codes] M6 = 9001"),
              std::string::npos)
        << usage.err;
}

TEST_F(CliTest, AnAddressCallsItsSubprogramWithItsValue) {
    write("shop/machine.toml", kFanucMill);
    write("shop/params.toml", "[params]\n6090 = 66\n");
    write("b.nc", "G90G00X5.B90.\nM30\nO9004\n#100=#146\n#101=#5041\nM99\n");
    ProcessResult check = sim({"check", "b.nc", "--config", "shop"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult r = sim({"run", "b.nc", "--config", "shop", "--print", "100,101"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"], json({{"100", 90.0}, {"101", 5.0}})) << r.out;
    EXPECT_EQ(j["machine"].value("B", -1.0), 0.0) << "B called O9004; it moved no axis";
}

namespace {

std::vector<std::string> messagesOf(const json& j) {
    std::vector<std::string> out;
    for (const json& m : j.value("messages", json::array())) {
        out.push_back(m.get<std::string>());
    }
    return out;
}

// A probing cycle as Renishaw-style packages write it: single block and feed hold off while the
// stylus is near the part, the feed override locked at 100 %, all given back at the end.
const char* const kProbeMove = "G90G00X0.\n#3003=1\n#3004=3\nG91G01X50.F600\nG01X-5.\n#3004=0\n#3003=0\n"
                               "G01X10.\nM30\n";

} // namespace

TEST_F(CliTest, SingleBlockDoesNotStopInsideAMacroThatSets3003) {
    write("probe.nc", kProbeMove);
    ProcessResult check = sim({"check", "probe.nc", "--dialect", "fanuc"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult r = sim({"run", "probe.nc", "--dialect", "fanuc", "--single-block"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(messagesOf(output(r)),
              (std::vector<std::string>{
                  "single block stop (probe.nc:1): START pressed (run without an operator)",
                  "single block stop (probe.nc:8): START pressed (run without an operator)"}));
}

TEST_F(CliTest, PauseIsHeldBackWhile3004SaysSo) {
    write("probe.nc", kProbeMove);
    // X50 at F600 runs from about 0 s to 5 s: PAUSE at 2 s waits for line 6
    ProcessResult r = sim({"run", "probe.nc", "--dialect", "fanuc", "--pause-at", "2"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(messagesOf(j),
              (std::vector<std::string>{
                  "PAUSE pressed at 2 s (probe.nc:4)",
                  "PAUSE held back: #3004 = 3 keeps feed hold off (probe.nc:4); the run holds where it "
                  "allows it again",
                  "PAUSE takes effect: #3004 allows feed hold again (probe.nc:6)",
                  "PAUSE: START pressed (run without an operator)"}))
        << r.out;
    EXPECT_DOUBLE_EQ(j["machine"].value("X", 0.0), 55.0) << r.out;
    // without #3004 the same PAUSE holds in the move
    write("plain.nc", "G90G00X0.\nG91G01X50.F600\nG01X-5.\nM30\n");
    ProcessResult plain = sim({"run", "plain.nc", "--dialect", "fanuc", "--pause-at", "2"});
    EXPECT_EQ(messagesOf(output(plain)),
              (std::vector<std::string>{"PAUSE pressed at 2 s (plain.nc:2)",
                                        "PAUSE: START pressed (run without an operator)"}))
        << plain.out;
}

TEST_F(CliTest, InterfaceSignalsAreTheMachineFoldersWiring) {
    write("cell/machine.toml",
          std::string(kFanucMill) +
              "[interface_signals]\nUI003 = \"IN05\"\nUI004 = \"IN06\"\nUO000 = \"OUT07\"\n"
              "UO101 = \"OUT08\"\n");
    // the pallet changer's macro: wait for pallet clamped (UI003), then signal done (UO000, UO101)
    write("pallet.nc", "WHILE[#1003EQ0]DO1\nEND1\n#100=#1032\n#1100=1\n#1133=2\n#101=#1132\nM30\n");
    ProcessResult check = sim({"check", "pallet.nc", "--config", "cell"});
    EXPECT_EQ(check.exitStatus, kExitOk) << check.err;
    ProcessResult r = sim({"run", "pallet.nc", "--config", "cell", "--input", "IN05=1", "--input", "IN06=1",
                           "--print", "100,101,1003,1004,1100,1133"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    json j = output(r);
    EXPECT_EQ(j["vars"],
              json({{"100", 24.0}, {"101", 1.0}, {"1003", 1.0}, {"1004", 1.0}, {"1100", 1.0}, {"1133", 2.0}}))
        << r.out;
    EXPECT_EQ(j["outputs"][6], 1) << "OUT07 follows UO000";
    EXPECT_EQ(j["outputs"][7], 1) << "OUT08 follows UO101";
    // the clamp never comes: the wait stops with the input named
    ProcessResult stuck = sim({"run", "pallet.nc", "--config", "cell", "--sensor-timeout", "1"});
    EXPECT_EQ(stuck.exitStatus, kExitAlarm);
    EXPECT_EQ(output(stuck)["alarm"].value("code", ""), "sensor_timeout") << stuck.out;
    // an input is not the macro's to write
    write("write.nc", "#1003=1\nM30\n");
    ProcessResult refused = sim({"check", "write.nc", "--config", "cell"});
    EXPECT_EQ(refused.exitStatus, kExitError);
    EXPECT_NE(refused.err.find("write.nc:1:1: cannot write #1003 (interface input UI003): it is read-only"),
              std::string::npos)
        << refused.err;
}

TEST_F(CliTest, TheBundledFanucMachinesWireTheirSignals) {
    const std::string machines = M350_MACHINES_DIR;
    // fanuc-umbrella: #1000-#1002 from the paper's ladder; the spindle holds T3
    write("t.nc", "T3\n#100=#1000\n#101=#1001\n#102=#1002\nT0\n#103=#1002\nM30\n");
    ProcessResult r = sim({"run", "t.nc", "--config", machines + "/fanuc-umbrella", "--tool", "3", "--print",
                           "100,101,102,103"});
    EXPECT_EQ(r.exitStatus, kExitOk) << r.err;
    EXPECT_EQ(output(r)["vars"], json({{"100", 1.0}, {"101", 0.0}, {"102", 0.0}, {"103", 1.0}})) << r.out;
}

// Programs for other controls meet a clear refusal at their line and column on every bundled FANUC
// machine: Haas's G103 (block look-ahead) and #10000-range variables, a Brother's G100 T1 tool change.
TEST_F(CliTest, ProgramsForOtherControlsAreRefusedWhereTheyStand) {
    const std::string machines = M350_MACHINES_DIR;
    write("haas.nc", "%\nO00010(HAAS VF2)\nG103P1\n#10100=5.\nG00X1.\nM30\n%\n");
    write("brother.nc", "%\nO0001(BROTHER S700)\nG90G00X0.Y0.\nG100T1\nM30\n%\n");
    for (const char* machine : {"fanuc-0i", "fanuc-umbrella", "fanuc-ts27r", "fanuc-30i"}) {
        const std::string config = machines + "/" + machine;
        ProcessResult haas = sim({"check", "haas.nc", "--config", config});
        EXPECT_EQ(haas.exitStatus, kExitError) << machine;
        EXPECT_NE(haas.err.find("haas.nc:3:1: G103: not a G code this machine knows"), std::string::npos)
            << machine << "\n"
            << haas.err;
        EXPECT_NE(haas.err.find("haas.nc:4:1: #10100 does not exist"), std::string::npos) << machine << "\n" << haas.err;
        ProcessResult run = sim({"run", "haas.nc", "--config", config});
        EXPECT_EQ(run.exitStatus, kExitAlarm) << machine;
        json a = output(run)["alarm"];
        EXPECT_EQ(a.value("code", ""), "invalid_word") << machine;
        EXPECT_EQ(a.value("line", 0), 3) << machine;
        EXPECT_EQ(a.value("column", 0), 1) << machine;
        ProcessResult brother = sim({"check", "brother.nc", "--config", config});
        EXPECT_EQ(brother.exitStatus, kExitError) << machine;
        EXPECT_NE(brother.err.find("brother.nc:4:1: G100: not a G code this machine knows"),
                  std::string::npos)
            << machine << "\n"
            << brother.err;
        ProcessResult changed = sim({"run", "brother.nc", "--config", config});
        EXPECT_EQ(changed.exitStatus, kExitAlarm) << machine;
        EXPECT_NE(changed.err.find("brother.nc:4:1: alarm: G100: not a G code this machine knows"),
                  std::string::npos)
            << machine << "\n"
            << changed.err;
    }
    // the variable alone, past the G103 line
    write("vars.nc", "#10100=5.\nM30\n");
    ProcessResult vars = sim({"run", "vars.nc", "--dialect", "fanuc"});
    EXPECT_EQ(vars.exitStatus, kExitAlarm);
    json a = output(vars)["alarm"];
    EXPECT_EQ(a.value("line", 0), 1);
    EXPECT_EQ(a.value("column", 0), 1);
    EXPECT_NE(a.value("message", "").find("10100"), std::string::npos) << vars.out;
    // unless the owner makes G100 a macro call: then the Brother's T1 is its argument #20
    write("brother-macro.nc", "G100T1\nM30\nO9010\n#100=#20\nM99\n");
    ProcessResult macro = sim({"run", "brother-macro.nc", "--config", machines + "/fanuc-0i", "--param",
                               "6050=100", "--print", "100"});
    EXPECT_EQ(macro.exitStatus, kExitOk) << macro.err;
    EXPECT_EQ(output(macro)["vars"].value("100", json()), 1.0) << macro.out;
}

} // namespace m350::clitest
