// check::StaticCheck on its own: a parsed program, the dialect and the machine's code programs are
// all it reads (no controller, no machine).
#include "core/check/StaticCheck.h"
#include "core/gcode/Parser.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;

std::vector<gcode::Diagnostic> checked(const std::string& text, const check::StaticCheck::CodePrograms& codes = {}) {
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
    EXPECT_EQ(checked("M150 X1 X2\nM30\n").size(), 1u);
    EXPECT_TRUE(checked("M150 X1 X2\nM30\n", {{{'M', 150}, 9001}}).empty());
}

} // namespace
