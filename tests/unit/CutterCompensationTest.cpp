#include "core/interp/CutterCompensation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace {

using m350::interp::CompensationError;
using m350::interp::CompensationSide;
using m350::interp::CutterCompensation;
using m350::interp::PathSegment;
using Side = CompensationSide;
using Path = std::vector<PathSegment>;

PathSegment L(double x0, double y0, double x1, double y1) {
    return PathSegment::line({x0, y0}, {x1, y1});
}
PathSegment A(double x0, double y0, double x1, double y1, double cx, double cy, bool cw) {
    return PathSegment::arc({x0, y0}, {x1, y1}, {cx, cy}, cw);
}
// G2 / G3 spelled out so the expectations read like the drawing.
constexpr bool CW = true;
constexpr bool CCW = false;

std::string show(const PathSegment& s) {
    std::string text = (s.kind == PathSegment::Kind::Line ? "L " : (s.clockwise ? "G2 " : "G3 "));
    text += "(" + std::to_string(s.start.x()) + "," + std::to_string(s.start.y()) + ")->(" +
            std::to_string(s.end.x()) + "," + std::to_string(s.end.y()) + ")";
    if (s.kind == PathSegment::Kind::Arc) {
        text += " c(" + std::to_string(s.center.x()) + "," + std::to_string(s.center.y()) + ")";
    }
    return text;
}

bool same(const PathSegment& a, const PathSegment& b) {
    constexpr double tol = 1e-9;
    if (a.kind != b.kind || (a.start - b.start).norm() > tol || (a.end - b.end).norm() > tol) {
        return false;
    }
    return a.kind == PathSegment::Kind::Line ||
           ((a.center - b.center).norm() <= tol && a.clockwise == b.clockwise);
}

void expectPath(const Path& got, const Path& want) {
    std::string gotText;
    for (const PathSegment& s : got) {
        gotText += "\n  " + show(s);
    }
    ASSERT_EQ(got.size(), want.size()) << "got:" << gotText;
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_TRUE(same(got[i], want[i]))
            << "segment " << i << ": got " << show(got[i]) << ", want " << show(want[i]);
    }
}

Path segments(const CutterCompensation::Result& r) {
    if (const auto* e = std::get_if<CompensationError>(&r)) {
        ADD_FAILURE() << e->message;
        return {};
    }
    return std::get<Path>(r);
}

std::string message(const CutterCompensation::Result& r) {
    const auto* e = std::get_if<CompensationError>(&r);
    return e ? e->message.english() : "no error";
}

// Feeds the whole program and collects every final segment, the flush at program end included.
Path run(const std::vector<std::pair<PathSegment, Side>>& program, double radius) {
    CutterCompensation cc;
    Path all;
    for (const auto& [segment, side] : program) {
        for (const PathSegment& s : segments(cc.feed(segment, side, radius))) {
            all.push_back(s);
        }
    }
    for (const PathSegment& s : cc.flush()) {
        all.push_back(s);
    }
    for (std::size_t i = 1; i < all.size(); ++i) {
        EXPECT_LT((all[i].start - all[i - 1].end).norm(), 1e-9) << "tool path breaks before " << show(all[i]);
    }
    return all;
}

// The 20 x 20 square with corners at X0/X20 Y0/Y20, traced counterclockwise from X10 Y0.
std::vector<std::pair<PathSegment, Side>> square(Side side, double entryFromY) {
    return {{L(10, entryFromY, 10, 0), side},
            {L(10, 0, 20, 0), side},
            {L(20, 0, 20, 20), side},
            {L(20, 20, 0, 20), side},
            {L(0, 20, 0, 0), side},
            {L(0, 0, 10, 0), side},
            {L(10, 0, 10, entryFromY), Side::Off}};
}

TEST(CutterCompensation, SquarePocketCcwWithG41TrimsInsideCorners) {
    // Tool on the left of a CCW path is inside the square: every corner is an inside corner and the
    // tool-center path is the 16 x 16 square 2 mm in from each side. The entry (as LinuxCNC's) ends
    // 2 mm to the left of its own line, on X12, trimmed where that meets the first side's offset.
    expectPath(run(square(Side::Left, 10), 2.0),
               {L(10, 10, 12, 2), L(12, 2, 18, 2), L(18, 2, 18, 18), L(18, 18, 2, 18), L(2, 18, 2, 2),
                L(2, 2, 10, 2), L(10, 2, 10, 10)});
}

TEST(CutterCompensation, EachFeedReturnsThePreviousSegmentUpToItsCorner) {
    CutterCompensation cc;
    expectPath(segments(cc.feed(L(10, 10, 10, 0), Side::Left, 2.0)), {});
    EXPECT_EQ(cc.side(), Side::Left);
    expectPath(segments(cc.feed(L(10, 0, 20, 0), Side::Left, 2.0)), {L(10, 10, 12, 2)});
    expectPath(segments(cc.feed(L(20, 0, 20, 20), Side::Left, 2.0)), {L(12, 2, 18, 2)});
    expectPath(segments(cc.feed(L(20, 20, 10, 10), Side::Off, 2.0)), {L(18, 2, 18, 20), L(18, 20, 10, 10)});
    EXPECT_EQ(cc.side(), Side::Off);
    EXPECT_FALSE(cc.hasPending());
}

TEST(CutterCompensation, SquareCcwWithG42GoesAroundOutsideCornersOnArcs) {
    // Tool on the right of a CCW path is outside: each corner gets a CCW quarter circle of radius 2
    // around the programmed corner.
    expectPath(run(square(Side::Right, -10), 2.0),
               {L(10, -10, 12, -2), L(12, -2, 20, -2), A(20, -2, 22, 0, 20, 0, CCW), L(22, 0, 22, 20),
                A(22, 20, 20, 22, 20, 20, CCW), L(20, 22, 0, 22), A(0, 22, -2, 20, 0, 20, CCW),
                L(-2, 20, -2, 0), A(-2, 0, 0, -2, 0, 0, CCW), L(0, -2, 10, -2), L(10, -2, 10, -10)});
}

TEST(CutterCompensation, G41OutsideCornerArcIsClockwise) {
    expectPath(
        run({{L(-10, 0, 0, 0), Side::Left}, {L(0, 0, 10, 0), Side::Left}, {L(10, 0, 10, -10), Side::Left}},
            2.0),
        {L(-10, 0, 0, 2), L(0, 2, 10, 2), A(10, 2, 12, 0, 10, 0, CW), L(12, 0, 12, -10)});
}

TEST(CutterCompensation, EntryEndsBesideItsOwnEndAndExitLeavesFromTheOffsetEnd) {
    CutterCompensation cc;
    // The entry runs diagonally and ends 2 mm to the left of its own end, as LinuxCNC's does; the
    // turn onto the next segment is an outside corner, so an arc follows around the corner.
    const double d = std::sqrt(2.0);
    expectPath(segments(cc.feed(L(-5, -5, 0, 0), Side::Left, 2.0)), {});
    expectPath(segments(cc.feed(L(0, 0, 10, 0), Side::Left, 2.0)), {L(-5, -5, -d, d), A(-d, d, 0, 2, 0, 0, CW)});
    // G40 without motion: the pending segment ends square to its own end, compensation stays on.
    expectPath(cc.flush(), {L(0, 2, 10, 2)});
    EXPECT_EQ(cc.side(), Side::Left);
    expectPath(segments(cc.feed(L(10, 0, 15, -5), Side::Off, 2.0)), {L(10, 2, 15, -5)});
    EXPECT_EQ(cc.side(), Side::Off);
    expectPath(segments(cc.feed(L(15, -5, 0, -5), Side::Off, 2.0)), {L(15, -5, 0, -5)});
}

TEST(CutterCompensation, EntryAndExitMustBeStraightAndTheEntryLongerThanTheRadius) {
    CutterCompensation cc;
    EXPECT_EQ(message(cc.feed(A(0, 0, 10, 0, 5, 0, CW), Side::Left, 2.0)),
              "cutter compensation must start on a straight move (G0/G1), not an arc");
    EXPECT_EQ(message(cc.feed(L(0, 0, 3, 0), Side::Left, 5.0)),
              "cutter compensation entry move of length 3.000 is not longer than the cutter radius 5.000");
    EXPECT_EQ(cc.side(), Side::Off);
    segments(cc.feed(L(0, 0, 10, 0), Side::Left, 2.0));
    EXPECT_EQ(message(cc.feed(A(10, 0, 20, 0, 15, 0, CW), Side::Off, 2.0)),
              "cutter compensation must end (G40) on a straight move, not an arc");
}

TEST(CutterCompensation, LineArcLineOffsetsTheArcRadius) {
    // Tangent profile: X0..10 along Y0, CCW quarter of R10 around X10 Y10, then up X20.
    const auto profile = [](Side side) {
        return std::vector<std::pair<PathSegment, Side>>{{L(0, -10, 0, 0), side},
                                                         {L(0, 0, 10, 0), side},
                                                         {A(10, 0, 20, 10, 10, 10, CCW), side},
                                                         {L(20, 10, 20, 20), side},
                                                         {L(20, 20, 20, 30), Side::Off}};
    };
    // G41 on a CCW arc: the tool is toward the center, R10 - 2 = 8.
    // (The entry, run +Y, ends left of its end at X-2 and turns the outside corner on an arc.)
    expectPath(run(profile(Side::Left), 2.0), {L(0, -10, -2, 0), A(-2, 0, 0, 2, 0, 0, CW), L(0, 2, 10, 2),
                                               A(10, 2, 18, 10, 10, 10, CCW), L(18, 10, 18, 20), L(18, 20, 20, 30)});
    // G42 on a CCW arc: away from the center, R10 + 2 = 12.
    expectPath(run(profile(Side::Right), 2.0),
               {L(0, -10, 2, -2), L(2, -2, 10, -2), A(10, -2, 22, 10, 10, 10, CCW), L(22, 10, 22, 20),
                L(22, 20, 20, 30)});
}

TEST(CutterCompensation, LineIntoArcCorner) {
    // X0..10 along Y0, then a CW half circle of R5 around X15 Y0 that leaves the corner going +Y.
    const auto profile = [](Side side) {
        return std::vector<std::pair<PathSegment, Side>>{
            {L(-10, 0, 0, 0), side}, {L(0, 0, 10, 0), side}, {A(10, 0, 20, 0, 15, 0, CW), side}};
    };
    // G42, a left turn: outside corner arc, then the CW arc shrunk to R3.
    expectPath(run(profile(Side::Right), 2.0), {L(-10, 0, 0, -2), L(0, -2, 10, -2),
                                                A(10, -2, 12, 0, 10, 0, CCW), A(12, 0, 18, 0, 15, 0, CW)});
    // G41: inside corner; the line Y2 meets the R7 offset circle at X 15 - sqrt(7^2 - 2^2).
    const double x = 15.0 - std::sqrt(45.0);
    expectPath(run(profile(Side::Left), 2.0), {L(-10, 0, 0, 2), L(0, 2, x, 2), A(x, 2, 22, 0, 15, 0, CW)});
}

TEST(CutterCompensation, CollinearContinuationHasNoCorner) {
    expectPath(
        run({{L(0, -10, 0, 0), Side::Left}, {L(0, 0, 10, 0), Side::Left}, {L(10, 0, 20, 0), Side::Left}},
            2.0),
        {L(0, -10, -2, 0), A(-2, 0, 0, 2, 0, 0, CW), L(0, 2, 10, 2), L(10, 2, 20, 2)});
}

TEST(CutterCompensation, ReversalGoesAroundTheEndOnAHalfCircle) {
    expectPath(
        run({{L(-10, 0, 0, 0), Side::Left}, {L(0, 0, 10, 0), Side::Left}, {L(10, 0, 0, 0), Side::Left}}, 2.0),
        {L(-10, 0, 0, 2), L(0, 2, 10, 2), A(10, 2, 10, -2, 10, 0, CW), L(10, -2, 0, -2)});
}

TEST(CutterCompensation, FullCircleKeepsItsCenter) {
    expectPath(run({{L(0, 0, 10, 0), Side::Left},
                    {A(10, 0, 10, 0, 0, 0, CCW), Side::Left},
                    {L(10, 0, 0, 0), Side::Off}},
                   2.0),
               // the entry's offset (Y2) meets the R8 circle at X sqrt(60): an inside corner
               {L(0, 0, std::sqrt(60.0), 2), A(std::sqrt(60.0), 2, 8, 0, 0, 0, CCW), L(8, 0, 0, 0)});
}

TEST(CutterCompensation, InsideCornerWithTooShortSegmentIsAGouge) {
    CutterCompensation cc;
    segments(cc.feed(L(0, 0, 0, 10), Side::Left, 5.0));
    segments(cc.feed(L(0, 10, 10, 10), Side::Left, 5.0));
    // Offsets Y15 and X5 meet at X5 Y15, 4 mm past the end of the 1 mm move.
    EXPECT_EQ(message(cc.feed(L(10, 10, 10, 11), Side::Left, 5.0)),
              "cutter radius 5.000 too large for the inside corner at X10.000 Y10.000 (gouge)");
    // The failed move changed nothing: a long enough one is still accepted.
    expectPath(segments(cc.feed(L(10, 10, 10, 30), Side::Left, 5.0)), {L(0, 15, 5, 15)});
}

TEST(CutterCompensation, SlotNarrowerThanTheToolIsAGougeAtItsSecondCorner) {
    // A 3 mm slot with a 4 mm tool: the first corner fits, the second one would make the tool back up
    // from Y2 to Y1 along X8.
    CutterCompensation cc;
    segments(cc.feed(L(0, -10, 0, 0), Side::Left, 2.0));
    segments(cc.feed(L(0, 0, 10, 0), Side::Left, 2.0));
    expectPath(segments(cc.feed(L(10, 0, 10, 3), Side::Left, 2.0)), {L(0, 2, 8, 2)});
    EXPECT_EQ(message(cc.feed(L(10, 3, 0, 3), Side::Left, 2.0)),
              "cutter radius 2.000 too large for the inside corner at X10.000 Y3.000 (gouge)");
}

TEST(CutterCompensation, ArcSmallerThanTheToolOnTheInsideIsAGouge) {
    CutterCompensation cc;
    segments(cc.feed(L(0, -10, 0, 0), Side::Left, 5.0));
    segments(cc.feed(L(0, 0, 10, 0), Side::Left, 5.0));
    EXPECT_EQ(message(cc.feed(A(10, 0, 10, 6, 10, 3, CCW), Side::Left, 5.0)),
              "cutter radius too large for the arc of radius 3.000 (gouge)");
    // On the outside the same arc just grows to R8.
    expectPath(run({{L(0, 10, 0, 0), Side::Right},
                    {L(0, 0, 10, 0), Side::Right},
                    {A(10, 0, 10, 6, 10, 3, CCW), Side::Right}},
                   5.0),
               {L(0, 10, -5, 0), A(-5, 0, 0, -5, 0, 0, CCW), L(0, -5, 10, -5), A(10, -5, 10, 11, 10, 3, CCW)});
}

TEST(CutterCompensation, NearlyTangentInsideTransitionIsTrimmedNotRejected) {
    // CAM rounding leaves the line 0.1 mrad off the tangent of the CW arc: a tiny inside corner whose
    // trim stays within the last 0.2 um of the line.
    const Path path = run({{L(-10, 10, -10, 0.001), Side::Left},
                           {L(-10, 0.001, 0, 0), Side::Left},
                           {A(0, 0, 10, -10, 0, -10, CW), Side::Left}},
                          2.0);
    ASSERT_EQ(path.size(), 3u);
    const Eigen::Vector2d trim = path[1].end;
    EXPECT_GT(trim.x(), 0.0);
    EXPECT_LT(trim.x(), 2e-4);
    EXPECT_NEAR((trim - Eigen::Vector2d(0, -10)).norm(), 12.0, 1e-9);
    EXPECT_TRUE(same(path[2], A(trim.x(), trim.y(), 12, -10, 0, -10, CW)));
}

TEST(CutterCompensation, RadiusChangeJoinsTheOffsetsWithALine) {
    CutterCompensation cc;
    segments(cc.feed(L(0, -10, 0, 0), Side::Left, 2.0));
    segments(cc.feed(L(0, 0, 10, 0), Side::Left, 2.0));
    expectPath(segments(cc.feed(L(10, 0, 20, 0), Side::Left, 3.0)), {L(0, 2, 10, 2), L(10, 2, 10, 3)});
    expectPath(segments(cc.feed(L(20, 0, 20, 10), Side::Left, 3.0)), {L(10, 3, 17, 3)});
}

TEST(CutterCompensation, RadiusZeroPassesThePathThrough) {
    CutterCompensation cc;
    expectPath(segments(cc.feed(L(0, 0, 10, 0), Side::Left, 0.0)), {L(0, 0, 10, 0)});
    expectPath(segments(cc.feed(A(10, 0, 20, 0, 15, 0, CW), Side::Left, 0.0)), {A(10, 0, 20, 0, 15, 0, CW)});
    EXPECT_EQ(cc.side(), Side::Off);
    expectPath(cc.flush(), {});
}

TEST(CutterCompensation, NegativeRadiusSwapsTheSide) {
    EXPECT_EQ(run(square(Side::Left, -10), -2.0).size(), run(square(Side::Right, -10), 2.0).size());
    expectPath(run(square(Side::Left, -10), -2.0), run(square(Side::Right, -10), 2.0));
}

TEST(CutterCompensation, ResumingAfterFlushAtAnOutsideCornerInsertsTheCornerArc) {
    CutterCompensation cc;
    segments(cc.feed(L(0, -10, 0, 0), Side::Right, 2.0));
    segments(cc.feed(L(0, 0, 10, 0), Side::Right, 2.0)); // the entry ends trimmed at X2 Y-2
    expectPath(cc.flush(), {L(2, -2, 10, -2)}); // e.g. a Z move at the corner
    expectPath(segments(cc.feed(L(10, 0, 10, 10), Side::Right, 2.0)), {A(10, -2, 12, 0, 10, 0, CCW)});
    expectPath(cc.flush(), {L(12, 0, 12, 10)});
}

TEST(CutterCompensation, SideSwitchAndBrokenPathAreRejected) {
    CutterCompensation cc;
    segments(cc.feed(L(0, -10, 0, 0), Side::Left, 2.0));
    EXPECT_EQ(message(cc.feed(L(0, 0, 10, 0), Side::Right, 2.0)),
              "cannot switch between G41 and G42 while compensating: program G40 first");
    EXPECT_EQ(message(cc.feed(L(5, 0, 10, 0), Side::Left, 2.0)),
              "programmed path is not continuous: the move from X5.000 Y0.000 follows one that ended at "
              "X0.000 Y0.000");
    cc.reset();
    EXPECT_EQ(cc.side(), Side::Off);
    EXPECT_FALSE(cc.hasPending());
}

} // namespace
