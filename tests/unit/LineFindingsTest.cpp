// A parsed line's findings: a syntax error abandons the line (LineFindings::Failure) and is filed
// with the file, the line and the column; a lint finding marks the line until the next one starts;
// a note changes nothing.
#include "core/gcode/LineFindings.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace m350;
using namespace m350::gcode;

TEST(LineFindings, FilesEachFindingWithItsFileLineAndColumn) {
    std::vector<Diagnostic> found;
    LineFindings findings(found, "part.nc");
    findings.startLine(7);
    findings.note(3, std::string("a note"));
    EXPECT_FALSE(findings.linted());
    findings.lint(5, std::string("a suspect line"));
    EXPECT_TRUE(findings.linted());
    EXPECT_EQ(findings.lastLint().message, "a suspect line");
    EXPECT_THROW(findings.fail(9, std::string("expected ']'")), LineFindings::Failure);
    ASSERT_EQ(found.size(), 3u);
    EXPECT_EQ(found[0].severity, Severity::Warning);
    EXPECT_EQ(found[1].severity, Severity::Error);
    EXPECT_EQ(found[1].kind, DiagnosticKind::Lint);
    EXPECT_EQ(found[2].kind, DiagnosticKind::Syntax);
    for (const Diagnostic& d : found) {
        EXPECT_EQ(d.file, "part.nc");
        EXPECT_EQ(d.line, 7u);
    }
    EXPECT_EQ(found[2].column, 9u);

    findings.startLine(8); // the next line starts without the last one's lint
    EXPECT_FALSE(findings.linted());
    findings.refuse(1, std::string(20000, 'x')); // filed, nothing thrown, echo clipped
    ASSERT_EQ(found.size(), 4u);
    EXPECT_EQ(found[3].line, 8u);
    EXPECT_LT(found[3].message.size(), 20000u);
}

} // namespace
