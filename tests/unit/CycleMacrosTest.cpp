// The default machine's canned-cycle macros (O9073 O9074 O9081-O9084 in slib-g.nc) against the
// interpreter's own cycles: the same program must move the machine through the same points.
#include "TracedRun.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using namespace m350;
using namespace m350::test;

// The moves, dwells and spindle switches of a run, without the moves that go nowhere (a macro's
// `G00 Z#10` when the tool is already at R) and without the macros' block times.
std::vector<std::string> motion(config::MachineConfig machine, const std::string& program) {
    TracedRun traced = runTraced(std::move(machine), program);
    EXPECT_RUN_OK(traced.run);
    std::vector<std::string> out;
    std::string at; // " X.. Y.. Z.." where the last move ended
    for (const std::string& e : traced.events) {
        if (e.rfind("rapid", 0) == 0 || e.rfind("feed", 0) == 0) {
            std::string to = e.substr(e.find(' '), e.find(" F") == std::string::npos ? std::string::npos
                                                                                      : e.find(" F") - e.find(' '));
            if (to == at) {
                continue; // a move to where the tool already is
            }
            at = to;
        }
        out.push_back(e);
    }
    return out;
}

config::MachineConfig withoutCycleMacros() {
    auto cfg = bundledMachine();
    cfg.libraries.clear(); // no slib-g.nc: the interpreter runs the cycles itself
    return cfg;
}

void expectSameMotion(const std::string& program) {
    auto macros = motion(bundledMachine(), program);
    auto native = motion(withoutCycleMacros(), program);
    EXPECT_EQ(macros, native) << program;
    EXPECT_GT(macros.size(), 4u);
}

TEST(CycleMacros, G81RepeatsOverHolesWithG98AndG99) {
    expectSameMotion(lines({"G90 G54 G00 X10 Y10 Z20", "G99 G81 X10 Y10 Z-5 R2 F300", "X30", "Y30", "G98 X50 R3",
                            "G80 G00 Z20", "M30"}));
}

TEST(CycleMacros, G82DwellsAtTheBottomAndKRepeats) {
    expectSameMotion(lines({"G90 G54 G00 X0 Y0 Z10", "G98 G82 X5 Y5 Z-3 R1 P500 F200 K2", "X15", "G80", "M30"}));
}

TEST(CycleMacros, G83AndG73Peck) {
    expectSameMotion(lines({"G90 G54 G00 X0 Y0 Z10", "G99 G83 X5 Y5 Z-10.5 R1 Q3 F200", "X15",
                            "G73 X25 Z-7 Q2.5", "G80 G00 Z10", "M30"}));
}

TEST(CycleMacros, TheClearanceComesFromParameter224) {
    auto program = lines({"G90 G54 G00 X0 Y0 Z10", "G98 G83 X5 Y5 Z-9 R1 Q3 F200", "G80", "M30"});
    auto macros = bundledMachine();
    macros.parameters.set(224, 1.5);
    auto native = withoutCycleMacros();
    native.parameters.set(224, 1.5);
    EXPECT_EQ(motion(macros, program), motion(native, program));
}

TEST(CycleMacros, G84AndG74Tap) {
    expectSameMotion(lines({"G90 G54 G00 X0 Y0 Z10", "M03 S500", "G99 G84 X5 Y5 Z-6 R2 P200 F500", "X15", "G80",
                            "M04 S500", "G74 X25 Y5 Z-6 R2 F500", "G80", "M05", "M30"}));
}

TEST(CycleMacros, ACycleStartedBelowRGoesUpToRFirst) {
    expectSameMotion(lines({"G90 G54 G00 X0 Y0 Z0", "G99 G81 X5 Y5 Z-5 R3 F300", "G80", "M30"}));
}

TEST(CycleMacros, UnderG91TheHandlerRefuses) {
    ProgramRun r = runProgram(bundledMachine(), lines({"G91 G81 X5 Y5 Z-5 R-2 F300", "M30"}));
    EXPECT_EQ(r.alarmText(), "invalid_word at " + r.fileName +
                                 ":1:5: G81 runs O9081, which takes absolute X Y Z R: program the cycle under G90");
}

TEST(CycleMacros, ZAndRAreNeeded) {
    ProgramRun r = runProgram(bundledMachine(), lines({"G90 G81 X5 Y5 Z-5 F300", "M30"}));
    EXPECT_EQ(r.alarmText(), "missing_address at " + r.fileName + ":1:5: G81 needs Z (the hole bottom) and R (the R level)");
}

} // namespace
