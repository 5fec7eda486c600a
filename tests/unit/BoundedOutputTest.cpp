// Issue 13: what a run or a parse produces stays bounded. A 13-byte `N1 M00 / GOTO1` program filled
// 9.3 GB with messages and trace lines; nested DOs made diagnostics quadratic. Each list keeps its
// first and last entries and says how many were left out.
#include "ParseSupport.h"
#include "RunProgram.h"
#include "tests/support/Sanitized.h"

#include "core/common/EchoText.h"
#include "core/controller/TraceWriter.h"
#include "core/gcode/DiagnosticCap.h"

#include <gtest/gtest.h>

#include <ctime>
#include <sstream>
#include <string>

namespace m350 {
namespace {

using controller::MessageLog;
using gcode::DiagnosticCap;
using gcode::DiagnosticKind;
using test::lines;

TEST(BoundedOutput, AnEndlessStopLoopKeepsTheFirstAndLastMessages) {
    controller::RunSettings settings;
    settings.maxSimTime = 2.0; // 2 blocks of 0.1 ms a pass: 10,000 passes, each posting a message
    auto run = test::runM350(lines({"N1 M00", "GOTO1"}), settings);
    ASSERT_TRUE(run.report.alarm);
    EXPECT_EQ(run.report.alarm->code, AlarmCode::SimulatedTimeLimit);
    const auto& messages = run.report.messages;
    ASSERT_EQ(messages.size(), MessageLog::kKeepFirst + 1 + MessageLog::kKeepLast);
    EXPECT_GT(run.report.messagesOmitted, 5000u);
    const std::string stop = "M00 program stop (" + run.fileName + ":1): START pressed (run without an operator)";
    EXPECT_EQ(messages.front(), stop);
    EXPECT_EQ(messages.back(), stop);
    EXPECT_EQ(messages[MessageLog::kKeepFirst], "… " + std::to_string(run.report.messagesOmitted) +
                                                    " more messages omitted (the first 2000 and the last 2000 are kept) …");
}

TEST(BoundedOutput, TheLastMessagesAreTheNewest) {
    // #3006 shows #1 each pass: the kept tail must end with the last pass, not stop at the cap.
    controller::RunSettings settings;
    auto run = test::runFanuc(lines({"#1 = 0", "WHILE [#1 LT 5000] DO1", "#1 = #1 + 1", "#3006 = 1 (PASS)", "END1",
                                     "M30"}),
                              settings);
    EXPECT_RUN_OK(run);
    ASSERT_EQ(run.report.messages.size(), 4001u);
    EXPECT_EQ(run.report.messagesOmitted, 1000u);
}

TEST(BoundedOutput, EchoedTextIsCutAtACharacterBoundary) {
    std::string chinese;
    for (int i = 0; i < 1000; ++i) {
        chinese += "对"; // 3 bytes each: a cut at 512 falls inside one
    }
    const std::string cut = clipEcho(chinese);
    EXPECT_EQ(cut.substr(0, 510), chinese.substr(0, 510));
    EXPECT_EQ(cut.substr(510), "… (2490 more bytes)");
    EXPECT_EQ(clipEcho("short"), "short");
}

TEST(BoundedOutput, ADiagnosticQuotingAHugeTokenIsCut) {
    const std::string word = "X1." + std::string(100000, '2') + ".5";
    auto p = gcode::support::parse("G1 " + word + "\n", gcode::Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1u) << gcode::support::listDiagnostics(p.diagnostics);
    EXPECT_LT(p.diagnostics[0].message.size(), kEchoLimit + 100);
    EXPECT_NE(p.diagnostics[0].message.find("more bytes)"), std::string::npos) << p.diagnostics[0].message;
}

// Before: one finding for every open DO1 on every DO1 line, n^2/2 of them.
TEST(BoundedOutput, DeeplyNestedLoopsGiveLinearBoundedDiagnostics) {
    constexpr int kDepth = 20000;
    std::string text;
    for (int i = 0; i < kDepth; ++i) {
        text += "WHILE [#1 LT 1] DO1\n";
    }
    // CPU time, not wall time: a loaded machine (CI, parallel ctest) must not fail it. The quadratic
    // parse this guards against takes minutes; the linear one 0.1 s in Release and, under the
    // sanitizers on a slow 2-core machine, 2.05 s (which failed a bound of 2 s).
    const double mostSeconds = test::kSanitized ? 20.0 : 2.0;
    const std::clock_t start = std::clock();
    auto p = gcode::support::parse(text, gcode::Dialect::fanuc());
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    EXPECT_LT(seconds, mostSeconds);
    // line 1: no END; lines 2..n: already open (naming the line before) and no END
    ASSERT_EQ(p.diagnostics.size(), DiagnosticCap::kKeepFirst + 1 + DiagnosticCap::kKeepLast);
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[1].line, 2u);
    EXPECT_NE(p.diagnostics[1].message.find("DO1 is already open (line 1)"), std::string::npos)
        << p.diagnostics[1].message;
    const gcode::Diagnostic& note = p.diagnostics[DiagnosticCap::kKeepFirst];
    EXPECT_EQ(note.omitted, 2u * kDepth - 1 - 1000);
    EXPECT_EQ(note.kind, DiagnosticKind::Flow);
    EXPECT_EQ(note.line, 251u) << "line 251's second finding is the first left out";
    EXPECT_EQ(p.diagnostics[DiagnosticCap::kKeepFirst - 1].line, 251u);
    EXPECT_NE(note.message.find(std::to_string(note.omitted) + " more findings omitted"), std::string::npos);
    EXPECT_EQ(p.diagnostics.back().line, static_cast<std::uint32_t>(kDepth));
    EXPECT_FALSE(gcode::hasBlockingError(p.diagnostics)) << "flow findings alarm only when reached";
}

TEST(BoundedOutput, AnOmittedSyntaxErrorStillStopsTheProgram) {
    std::string text;
    for (int i = 0; i < 3000; ++i) {
        text += i == 1500 ? "G1 X1.2.3\n" : "IF [#1 EQ 1] GOTO 99\n";
    }
    auto p = gcode::support::parse(text, gcode::Dialect::fanuc());
    ASSERT_EQ(p.diagnostics.size(), 1001u);
    for (std::size_t i = 0; i < p.diagnostics.size(); ++i) {
        if (i != DiagnosticCap::kKeepFirst) {
            EXPECT_EQ(p.diagnostics[i].kind, DiagnosticKind::Flow) << i;
        }
    }
    EXPECT_EQ(p.diagnostics[DiagnosticCap::kKeepFirst].kind, DiagnosticKind::Syntax);
    EXPECT_TRUE(gcode::hasBlockingError(p.diagnostics));
}

TEST(BoundedOutput, TheTraceKeepsItsFirstAndLastLinesWithinItsLimit) {
    std::ostringstream out;
    controller::TraceWriter trace(out, 64 * 1024);
    for (int i = 0; i < 10000; ++i) {
        trace.runState(i, i % 2 ? "pause" : "resume");
    }
    trace.finish();
    const std::string text = out.str();
    EXPECT_LE(text.size(), 64u * 1024);
    EXPECT_EQ(text.substr(0, text.find('\n')), R"({"t":0.0,"type":"resume"})");
    EXPECT_EQ(text.substr(text.rfind('\n', text.size() - 2) + 1), "{\"t\":9999.0,\"type\":\"pause\"}\n");
    const std::size_t note = text.find(R"("type":"trace_truncated")");
    ASSERT_NE(note, std::string::npos);
    std::size_t kept = 0;
    for (char c : text) {
        kept += c == '\n' ? 1 : 0;
    }
    EXPECT_NE(text.find("\"omitted_lines\":" + std::to_string(10000 - (kept - 1))), std::string::npos)
        << text.substr(note - 200, 400);
}

TEST(BoundedOutput, ATraceUnderItsLimitIsUntouched) {
    std::ostringstream out;
    controller::TraceWriter trace(out, 64 * 1024);
    trace.runState(1.5, "pause");
    trace.finish();
    EXPECT_EQ(out.str(), "{\"t\":1.5,\"type\":\"pause\"}\n");
}

// 2,000 DPRNT records `PASS    n` through a 4,000-byte limit.
test::ProgramRun passesThroughASmallLimit() {
    controller::RunSettings settings;
    settings.externalOutputLimit = 4000;
    return test::runFanuc(lines({"#1 = 0", "POPEN", "WHILE [#1 LT 2000] DO1", "#1 = #1 + 1", "DPRNT[PASS#1[40]]",
                                 "END1", "PCLOS", "M30"}),
                          settings);
}

TEST(BoundedOutput, ExternalOutputInALoopKeepsItsFirstAndLastRecords) {
    auto run = passesThroughASmallLimit();
    EXPECT_RUN_OK(run);
    const std::string out = run.controller->externalDevices().received();
    EXPECT_LT(out.size(), 4200u);
    EXPECT_EQ(out.substr(0, 10), "PASS    1\n");
    EXPECT_EQ(out.substr(out.size() - 10), "PASS 2000\n");
    EXPECT_NE(out.find(" records ("), std::string::npos);
    EXPECT_NE(out.find("omitted: the output reached its limit"), std::string::npos);
}

// What the panel's system log reads: each record once, in order, also the ones externalOutput()
// leaves out past its limit.
TEST(BoundedOutput, EveryExternalRecordIsHandedOverPastTheLimit) {
    auto run = passesThroughASmallLimit();
    EXPECT_RUN_OK(run);
    EXPECT_TRUE(run.controller->externalDevices().outputCapped());
    const controller::ExternalDevices::NewRecords fresh = run.controller->externalDevices().takeNewRecords();
    EXPECT_EQ(fresh.missed, 0u);
    ASSERT_EQ(fresh.records.size(), 2000u);
    for (std::size_t i = 0; i < fresh.records.size(); ++i) {
        ASSERT_EQ(fresh.records[i].rfind("PASS", 0), 0u) << fresh.records[i];
        ASSERT_EQ(std::stoi(fresh.records[i].substr(4)), static_cast<int>(i + 1)) << fresh.records[i];
    }
    EXPECT_TRUE(run.controller->externalDevices().takeNewRecords().records.empty()) << "taken once";
}

// A run nobody takes records from (m350-sim) holds only the newest megabyte of them.
TEST(BoundedOutput, RecordsNobodyTakesWaitWithinTheirBudget) {
    auto run = test::runFanuc(lines({"#1 = 0", "POPEN", "WHILE [#1 LT 80000] DO1", "#1 = #1 + 1",
                                     "DPRNT[RECORD*NUMBER*#1[60]]", "END1", "PCLOS", "M30"}));
    EXPECT_RUN_OK(run);
    EXPECT_FALSE(run.controller->externalDevices().outputCapped()) << "1.7 MB is within the default 64 MiB";
    const controller::ExternalDevices::NewRecords fresh = run.controller->externalDevices().takeNewRecords();
    std::size_t bytes = 0;
    for (const std::string& record : fresh.records) {
        bytes += record.size();
    }
    EXPECT_LE(bytes, controller::ExternalDevices::kNewRecordsBudget);
    EXPECT_GT(bytes, controller::ExternalDevices::kNewRecordsBudget - 100);
    EXPECT_GT(fresh.missed, 0u);
    EXPECT_EQ(fresh.missed + fresh.records.size(), 80000u);
    ASSERT_FALSE(fresh.records.empty());
    EXPECT_EQ(fresh.records.back(), "RECORD NUMBER   80000\n");
}

} // namespace
} // namespace m350
