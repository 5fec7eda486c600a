// FANUC's look-ahead and contour-control codes (G05.1 Q1/Q0, G08 P1/P0, G05 P10000/P0): accepted
// on the fanuc machine, recorded in the trace, the path unchanged; refused on the M350.
#include "TracedRun.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace m350;
using test::lines;

// The look-ahead events of a traced run: "G05.1 Q1 R5 @2" (code and source line).
std::vector<std::string> lookAheadEvents(const std::string& trace) {
    std::vector<std::string> out;
    std::istringstream in(trace);
    for (std::string line; std::getline(in, line);) {
        auto event = nlohmann::json::parse(line);
        if (event["type"] == "lookahead") {
            out.push_back(event["code"].get<std::string>() + " @" + std::to_string(event["line"].get<int>()));
        }
    }
    return out;
}

const char* const kPath[] = {"G90 G1 X10 F1000", "G1 X20 Y5", "G1 X0", "G81 X5 Y5 Z-3 R1", "X6", "G80", "M30"};

std::string withCodes(std::initializer_list<std::pair<std::size_t, const char*>> inserts) {
    std::string text;
    for (std::size_t i = 0; i < std::size(kPath); ++i) {
        for (auto [before, code] : inserts) {
            if (before == i) {
                text += std::string(code) + "\n";
            }
        }
        text += std::string(kPath[i]) + "\n";
    }
    return text;
}

TEST(LookAheadCodes, FanucAcceptsThemAndMovesAlongTheSamePath) {
    auto plain = test::runTraced(test::fanucMachine(), withCodes({}));
    std::ostringstream trace;
    controller::RunSettings settings;
    settings.trace = &trace;
    // G05.1 Q0 also inside the active G81: its Q is no peck depth and it drills no hole
    std::string program = withCodes({{0, "G05.1 Q1 R5"}, {1, "G08 P1"}, {2, "G05 P10000"}, {5, "G05.1 Q0"},
                                     {6, "G05 P0"}, {6, "G08 P0"}});
    auto coded = test::runTraced(test::fanucMachine(), program);
    EXPECT_RUN_OK(plain.run);
    EXPECT_RUN_OK(coded.run);
    EXPECT_EQ(coded.events, plain.events);

    auto run = test::runProgram(test::fanucMachine(), program, settings);
    EXPECT_RUN_OK(run);
    EXPECT_EQ(lookAheadEvents(trace.str()),
              (std::vector<std::string>{"G05.1 Q1 R5 @1", "G08 P1 @3", "G05 P10000 @5", "G05.1 Q0 @9", "G05 P0 @11",
                                        "G08 P0 @12"}));
}

struct Refusal {
    const char* line;
    std::uint32_t column;
    const char* message;
};

TEST(LookAheadCodes, MalformedOnesAlarmAtTheirColumn) {
    const Refusal refusals[] = {
        {"G05.1", 1, "G5.1: write G05.1 Q1 (AI contour control on) or G05.1 Q0 (off)"},
        {"G05.1 Q2", 7, "Q2: write G05.1 Q1 (AI contour control on) or G05.1 Q0 (off)"},
        {"G08 P5", 5, "P5: write G08 P1 (look-ahead control on) or G08 P0 (off)"},
        {"G05 P3", 5, "P3: write G05 P10000 (high-precision contour control on) or G05 P0 (off)"},
        {"G05.1 Q1 X10", 1, "G5.1: G05.1 stands in a block of its own: G05.1 Q1 (AI contour control on)"},
    };
    for (const Refusal& r : refusals) {
        auto run = test::runFanuc(lines({"G90", r.line, "M30"}));
        ASSERT_TRUE(run.report.alarm) << r.line;
        EXPECT_EQ(run.report.alarm->code, AlarmCode::InvalidWord) << r.line;
        EXPECT_EQ(run.report.alarm->line, 2u) << r.line;
        EXPECT_EQ(run.report.alarm->column, r.column) << r.line;
        EXPECT_EQ(run.report.alarm->message.rfind(r.message, 0), 0u) << run.report.alarm->message;
    }
}

TEST(LookAheadCodes, M350KnowsNoneOfThem) {
    for (const char* line : {"G05.1 Q1", "G08 P1", "G05 P10000"}) {
        auto run = test::runM350(lines({"G90", line, "M30"}));
        ASSERT_TRUE(run.report.alarm) << line;
        EXPECT_EQ(run.report.alarm->code, AlarmCode::InvalidWord) << line;
        EXPECT_NE(run.report.alarm->message.find("not a G code this machine knows"), std::string::npos)
            << run.report.alarm->message;
    }
}

} // namespace
