// check::StaticCheck on its own: a parsed program, the dialect and the machine's code programs are
// all it reads (no controller, no machine).
#include "core/check/StaticCheck.h"
#include "core/gcode/Parser.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;

std::vector<gcode::Diagnostic> checked(const std::string& text, const macro::CallCodes& codes = {}) {
    gcode::Parser parser(gcode::Dialect::m350());
    gcode::Program program;
    parser.addFile(program, "main.nc", text, gcode::FileRole::Main);
    parser.finish(program);
    return check::StaticCheck(program, gcode::Dialect::m350(), codes).findings();
}

TEST(StaticCheck, FindsWhatTheRunWouldAlarmOnWithoutAController) {
    std::vector<gcode::Diagnostic> found = checked("G1 X1 X2\n#1=1/0\nM30\n");
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].line, 1u);
    EXPECT_EQ(found[0].message, "X appears twice in one block");
    EXPECT_EQ(found[1].line, 2u);
}

TEST(StaticCheck, AMachineCodeProgramTakesItsBlocksWords) {
    // without the code the block is the M350's: M150 has no handler and X is there twice
    const std::vector<gcode::Diagnostic> plain = checked("M150 X1 X2\nM30\n");
    ASSERT_EQ(plain.size(), 2u);
    EXPECT_EQ(plain[0].message, "M150: no such M code (and no O10150 handler in slib-m.nc)");
    EXPECT_EQ(plain[1].message, "X appears twice in one block");
    macro::CallCodes codes;
    codes.add('M', 150, {9001, macro::CallKind::Subprogram, 0, "[codes] M150 = 9001"});
    EXPECT_TRUE(checked("M150 X1 X2\nM30\n", codes).empty());
}

TEST(StaticCheck, ABlockWithACallingAddressTakesItsWords) {
    EXPECT_EQ(checked("G0 X1 X2 B5\nM30\n").size(), 1u);
    macro::CallCodes codes;
    codes.addAddress('B', {9004, macro::CallKind::Subprogram, 146, "parameter 6090 = 66"});
    EXPECT_TRUE(checked("G0 X1 X2 B5\nM30\n", codes).empty());
}

// Probing macros clear G31's result per axis before the next probe (`#1922=0 ;clear probe status
// before retract`): #1920-#1924 are written on the controller; the trigger positions are not.
TEST(StaticCheck, TheProbeResultsMayBeClearedButNotTheTriggerPositions) {
    EXPECT_TRUE(checked("#1920=0\n#1921=0\n#1922=0 ;clear probe status before retract\n#1924=0\nM30\n").empty());
    for (int n = 1925; n <= 1929; ++n) {
        std::vector<gcode::Diagnostic> found = checked("#" + std::to_string(n) + "=0\nM30\n");
        ASSERT_EQ(found.size(), 1u) << n;
        EXPECT_NE(found[0].message.find("read-only"), std::string::npos) << found[0].message;
    }
}

} // namespace
