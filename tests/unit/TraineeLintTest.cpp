// check::TraineeLint and the parser's lints for trainees' macros (issue 28): each fires on the
// mistake, at its line and column, and keeps quiet on the form that was meant.
#include "core/check/StaticCheck.h"
#include "core/check/TraineeLint.h"
#include "core/gcode/Parser.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace m350;

struct Found {
    std::vector<gcode::Diagnostic> all;
    std::vector<gcode::Diagnostic> with(const std::string& id) const {
        std::vector<gcode::Diagnostic> out;
        for (const gcode::Diagnostic& d : all) {
            if (d.messageId == id) {
                out.push_back(d);
            }
        }
        return out;
    }
};

// What `m350-sim check --lint` says of a main program: the parser's findings, then the lints.
Found linted(const std::string& text, const gcode::Dialect& dialect = gcode::Dialect::m350()) {
    gcode::Parser parser(dialect);
    gcode::Program program;
    parser.addFile(program, "main.nc", text, gcode::FileRole::Main);
    parser.finish(program);
    Found found{parser.diagnostics()};
    for (const gcode::Diagnostic& d : check::TraineeLint(program, dialect).findings(0)) {
        found.all.push_back(d);
    }
    return found;
}

TEST(TraineeLint, AGotoToALabelThisProgramDoesNotHave) {
    for (const gcode::Dialect* dialect : {&gcode::Dialect::m350(), &gcode::Dialect::fanuc()}) {
        const Found wrong = linted("O1\nIF [#100 EQ 1] GOTO20\nM30\nO2\nN20 M99\n", *dialect);
        ASSERT_EQ(wrong.with("flow_goto_no_label").size(), 1u);
        EXPECT_EQ(wrong.with("flow_goto_no_label")[0].line, 2u);
        EXPECT_EQ(wrong.with("flow_goto_no_label")[0].column, 20u); // the label it names
        EXPECT_TRUE(linted("O1\nIF [#100 EQ 1] GOTO20\nN20 M30\n", *dialect).all.empty());
    }
}

TEST(TraineeLint, AToolNumberAddedToAPocketCoordinate) {
    const Found wrong = linted("G53 X[#1330+#1300-1]\nM30\n");
    ASSERT_EQ(wrong.with("lint_table_added").size(), 1u);
    EXPECT_EQ(wrong.with("lint_table_added")[0].line, 1u);
    EXPECT_EQ(wrong.with("lint_table_added")[0].column, 5u);
    EXPECT_NE(wrong.with("lint_table_added")[0].message.find("X#[1330+#1300-1]"), std::string::npos);
    EXPECT_TRUE(linted("G53 X#[1330+#1300-1]\nM30\n").all.empty());
}

TEST(TraineeLint, AnInputWaitWithNoWayOut) {
    const Found wrong = linted("#13=7\nM05\nWHILE [#[1520+#13-1] NE 0] DO1\nG04 P10\nEND1\nM30\n");
    ASSERT_EQ(wrong.all.size(), 1u);
    EXPECT_EQ(wrong.all[0].messageId, "lint_input_wait");
    EXPECT_EQ(wrong.all[0].severity, gcode::Severity::Warning);
    EXPECT_EQ(wrong.all[0].line, 3u);
    EXPECT_EQ(wrong.all[0].column, 1u);
    EXPECT_NE(wrong.all[0].message.find("#[1520+#13-1]"), std::string::npos) << wrong.all[0].message;
    // counted, with an alarm after the limit: quiet
    EXPECT_TRUE(linted("#30=0\nWHILE [[#1520 NE 0]*[#30 LT 500]] DO1\nG04 P10\n#30=#30+1\nEND1\n"
                       "IF [#30 LT 500] GOTO1\n#1503=1(IN01 not off)\nM30\nN1 M30\n")
                    .all.empty());
    // FANUC: #1000-#1015 are the interface inputs; a counter or a jump leaves the loop
    const Found fanuc = linted("WHILE [#1002 EQ 0] DO1\nG04 X0.1\nEND1\nM30\n", gcode::Dialect::fanuc());
    ASSERT_EQ(fanuc.with("lint_input_wait").size(), 1u);
    EXPECT_TRUE(linted("#1=0\nWHILE [#1002 EQ 0] DO1\nG04 X0.1\n#1=#1+1\nIF [#1 GT 50] GOTO9\nEND1\nN9 M30\n",
                       gcode::Dialect::fanuc())
                    .all.empty());
    // a loop on a counter reads no input
    EXPECT_TRUE(linted("#20=0\nWHILE [#20 LT 3] DO1\n#20=#20+1\nEND1\nM30\n").all.empty());
}

TEST(TraineeLint, AVariableReadBeforeItIsSet) {
    const Found wrong = linted("#1=10\nG0 X#1 Y#2\nM30\n");
    ASSERT_EQ(wrong.all.size(), 1u);
    EXPECT_EQ(wrong.all[0].messageId, "lint_read_before_set");
    EXPECT_EQ(wrong.all[0].line, 2u);
    EXPECT_EQ(wrong.all[0].column, 9u);
    EXPECT_TRUE(linted("#1=10\n#2=5\nG0 X#1 Y#2\nM30\n").all.empty());
    // FANUC: testing an argument against #0 is how a macro asks whether it was given
    EXPECT_EQ(linted("#2=#1+1\nM30\n", gcode::Dialect::fanuc()).with("lint_read_before_set").size(), 1u);
    EXPECT_TRUE(linted("IF [#1 EQ #0] GOTO9\nN9 M30\n", gcode::Dialect::fanuc()).all.empty());
    // a macro program's locals are its arguments
    EXPECT_TRUE(linted("O9010\nG0 X#24\nM99\n", gcode::Dialect::fanuc()).all.empty());
}

TEST(TraineeLint, AnOutputSwitchedOnAndNeverOffOnSomePath) {
    const Found wrong = linted("#1552=1\nIF [#1521 EQ 1] GOTO9\n#1552=0\nN9 M30\n");
    ASSERT_EQ(wrong.all.size(), 1u);
    EXPECT_EQ(wrong.all[0].messageId, "lint_output_left_on");
    EXPECT_EQ(wrong.all[0].line, 1u);
    EXPECT_EQ(wrong.all[0].column, 1u);
    EXPECT_NE(wrong.all[0].message.find("M30 on line 4"), std::string::npos) << wrong.all[0].message;
    EXPECT_TRUE(linted("#1552=1\nIF [#1521 EQ 1] GOTO9\n#1552=0\nM30\nN9 #1552=0\nM30\n").all.empty());
    // the factory's indexed form, in a program that clamps on one path and returns on another
    const Found indexed =
        linted("O3\n#20=1\n#[1552+#20-1]=1\nIF [#1 GT 8] GOTO5\n#[1552+#20-1]=0\nN5 M99\n");
    ASSERT_EQ(indexed.with("lint_output_left_on").size(), 1u);
    EXPECT_NE(indexed.with("lint_output_left_on")[0].message.find("#[1552+#20-1]"), std::string::npos);
    // a handler that only switches on (M8's coolant) leaves it on by design
    EXPECT_TRUE(linted("O10008\n#1554=1\nM99\n").all.empty());
    // FANUC #1100-#1115
    EXPECT_EQ(linted("#1100=1\nM30\n", gcode::Dialect::fanuc()).with("lint_output_left_on").size(), 1u);
    EXPECT_TRUE(linted("#1100=1\nG04 X1.\n#1100=0\nM30\n", gcode::Dialect::fanuc()).all.empty());
}

TEST(TraineeLint, M30RightAfterM6) {
    const Found wrong = linted("T2 M6\nM30\n");
    ASSERT_EQ(wrong.all.size(), 1u);
    EXPECT_EQ(wrong.all[0].messageId, "lint_m30_after_m6");
    EXPECT_EQ(wrong.all[0].line, 2u);
    EXPECT_EQ(wrong.all[0].column, 1u);
    EXPECT_EQ(linted("T2 M6 M30\n").with("lint_m30_after_m6").size(), 1u);
    EXPECT_TRUE(linted("T2 M6\nG04 P500\nM30\n").all.empty());
}

TEST(TraineeLint, ANestedParenthesisInAComment) {
    for (const gcode::Dialect* dialect : {&gcode::Dialect::m350(), &gcode::Dialect::fanuc()}) {
        const Found wrong = linted("G0 X1 (rough (T1) pass)\nM30\n", *dialect);
        ASSERT_EQ(wrong.with("lint_comment_nested").size(), 1u);
        EXPECT_EQ(wrong.with("lint_comment_nested")[0].line, 1u);
        EXPECT_EQ(wrong.with("lint_comment_nested")[0].column, 14u);
        EXPECT_EQ(wrong.with("lint_comment_nested")[0].severity, gcode::Severity::Warning);
        EXPECT_TRUE(linted("G0 X1 (rough [T1] pass)\nM30\n", *dialect).all.empty());
    }
    // counted in characters: 粗 is one
    EXPECT_EQ(linted("G0 X1 (粗 (T1))\nM30\n").with("lint_comment_nested")[0].column, 10u);
}

} // namespace
