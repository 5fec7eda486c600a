// The machine view's path (core/preview): the moves a program's run makes, with their lines, in
// machine coordinates; arcs kept as arcs; coarser levels for small views; a budget that keeps a
// huge program's preview in bounded memory.
#include "tests/unit/RunProgram.h"

#include "core/preview/ArcPoints.h"
#include "core/preview/PreviewBuilder.h"

#include <atomic>
#include <cmath>

namespace m350::test {

namespace {

struct Flat {
    preview::Point3 from;
    preview::PathSegment segment;
    std::optional<preview::ArcCentre> centre;
};

std::vector<Flat> flatten(const preview::PathStore& store) {
    std::vector<Flat> out;
    for (const auto& chunk : store.chunks()) {
        preview::Point3 at = chunk.start;
        std::size_t arc = 0;
        for (const auto& s : chunk.segments) {
            out.push_back({at, s, s.arc() ? std::optional(chunk.arcs[arc++]) : std::nullopt});
            at = s.end;
        }
    }
    return out;
}

} // namespace

TEST(PathPreview, EveryMoveWithItsLineInMachineCoordinates) {
    config::MachineConfig machine = m350Machine();
    machine.offsets[1][0] = -300.0; // G54 X-300: work X0 is machine X-300
    const std::string program = writeTempFile(lines({
        "G54 G90 G17",
        "G0 X10 Y20",       // 2
        "G1 Z-5 F600",      // 3
        "G2 X30 Y20 I10 J0", // 4: a half circle about X20 Y20, clockwise
        "G0 Z0",            // 5
        "M30",
    }));
    preview::Preview p = preview::buildPreview(machine, program);
    ASSERT_TRUE(p.loaded);
    ASSERT_FALSE(p.alarm) << p.alarm->message;
    std::vector<Flat> moves = flatten(p.path);
    ASSERT_EQ(moves.size(), 4u);
    EXPECT_EQ(moves[0].segment.kind, preview::SegmentKind::Rapid);
    EXPECT_EQ(moves[0].segment.line, 2u);
    EXPECT_FLOAT_EQ(moves[0].segment.end.x, -290.0F);
    EXPECT_FLOAT_EQ(moves[0].segment.end.y, 20.0F);
    EXPECT_EQ(moves[1].segment.kind, preview::SegmentKind::Feed);
    EXPECT_EQ(moves[1].segment.line, 3u);
    EXPECT_FLOAT_EQ(moves[1].segment.end.z, -5.0F);
    const Flat& arc = moves[2];
    EXPECT_EQ(arc.segment.kind, preview::SegmentKind::ArcCw);
    EXPECT_EQ(arc.segment.line, 4u);
    ASSERT_TRUE(arc.centre);
    EXPECT_FLOAT_EQ(arc.centre->u, -280.0F);
    EXPECT_FLOAT_EQ(arc.centre->v, 20.0F);
    // clockwise from about X-280 goes over the top: its middle is at Y30
    const preview::PlanarArc planar(arc.from, arc.segment, *arc.centre);
    EXPECT_NEAR(planar.at(0.5).x, -280.0, 1e-4);
    EXPECT_NEAR(planar.at(0.5).y, 30.0, 1e-4);
    EXPECT_EQ(p.path.files().at(moves[2].segment.file), std::filesystem::path(program).filename().string());
    // the box holds the arc's top, not only its ends
    EXPECT_GE(p.path.bounds().max.y, 30.0F - 1e-4F);
    EXPECT_LE(p.path.bounds().min.x, -290.0F);
}

TEST(PathPreview, AProgramOverTheBudgetIsMergedNotDropped) {
    std::string text = "G90 G1 F1000\n";
    for (int i = 0; i < 20000; ++i) {
        // a fine zigzag along X: 0.01 mm steps, 200 mm long
        text += "X" + std::to_string(i * 0.01) + " Y" + std::to_string(i % 2 == 0 ? 0.0 : 0.005) + "\n";
    }
    text += "G0 X0 Y50\nM30\n";
    preview::PreviewSettings settings;
    settings.segmentBudget = 1000;
    preview::Preview p = preview::buildPreview(m350Machine(), writeTempFile(text), settings);
    ASSERT_TRUE(p.loaded);
    EXPECT_EQ(p.moves, 20001u);
    EXPECT_GT(p.coarsenedTo, 0.0);
    EXPECT_LE(p.path.size(), 1000u);
    // no coarser than the budget needs: 200 mm in 1000 moves is 0.2 mm a move (the tolerance
    // doubled at every budget hit went to metres)
    EXPECT_LT(p.coarsenedTo, 1.0);
    // the whole program is still there: it ends where the program does, the last rapid a rapid
    const preview::Point3 end = p.path.position();
    EXPECT_FLOAT_EQ(end.x, 0.0F);
    EXPECT_FLOAT_EQ(end.y, 50.0F);
    EXPECT_NEAR(p.path.bounds().max.x, 199.99, p.coarsenedTo);
    std::vector<Flat> moves = flatten(p.path);
    EXPECT_EQ(moves.back().segment.kind, preview::SegmentKind::Rapid);
    EXPECT_LT(p.path.bytes(), 1000u * 40u + 4 * sizeof(preview::PathStore::Chunk) + 200000u);
}

// A CAM raster with half circles (arcs a third of the moves): past the budget the arcs merge
// too, at the tolerance the path's length needs, not more.
TEST(PathPreview, ARasterWithArcsOverTheBudgetIsMergedToTheToleranceItNeeds) {
    std::string text = "G90 G17 G1 F1500\n";
    double x = 0.0, y = 0.0;
    int dir = 1;
    for (int i = 0; i < 30000; ++i) {
        if (i % 3 == 2) {
            const double to = x + 2.0 * dir;
            text += std::string(dir > 0 ? "G2" : "G3") + " X" + std::to_string(to) + " Y" + std::to_string(y) + " I" +
                    std::to_string(double(dir)) + " J0\n";
            x = to;
        } else {
            if (x > 200.0 || x < 0.0) {
                dir = -dir;
                y += 0.2;
            }
            x += 0.05 * dir;
            text += "G1 X" + std::to_string(x) + " Y" + std::to_string(y) + "\n";
        }
    }
    text += "M30\n";
    preview::PreviewSettings settings;
    settings.segmentBudget = 3000;
    preview::Preview p = preview::buildPreview(m350Machine(), writeTempFile(text), settings);
    ASSERT_TRUE(p.loaded);
    EXPECT_LE(p.path.size(), 3000u);
    // the path is about 10,000 half circles of pi mm and 20,000 steps of 0.05 mm: 32,400 mm,
    // so 1,500 moves (half the budget) of about 22 mm would do; four times that is the bound
    EXPECT_GT(p.coarsenedTo, 0.0);
    EXPECT_LT(p.coarsenedTo, 4.0 * 22.0) << "merged " << p.path.size();
}

// A build nobody waits for any more stops at its next few thousand moves, inside the run of an
// endless program, and says it was cancelled (the preview's own controller is left by an
// exception: the sanitizer build runs this too).
TEST(PathPreview, ACancelledBuildStopsInsideTheRun) {
    const std::string program = writeTempFile("#1=0\nWHILE[#1 LT 1]DO1\nG1 X10 F60000\nG1 X0\nEND1\nM30\n");
    std::atomic<bool> cancel{true}; // cancelled before it starts: it stops at its first check
    preview::PreviewSettings settings;
    settings.cancel = &cancel;
    const preview::Preview p = preview::buildPreview(m350Machine(), program, settings);
    EXPECT_TRUE(p.loaded);
    EXPECT_TRUE(p.cancelled);
    EXPECT_EQ(p.moves, 4096u) << "the first check comes at 4,096 moves";
    cancel = false;
    settings.maxSimTime = 2000.0; // not cancelled: the endless loop ends at the time limit
    const preview::Preview whole = preview::buildPreview(m350Machine(), program, settings);
    EXPECT_FALSE(whole.cancelled);
    EXPECT_GT(whole.moves, 4096u);
}

TEST(PathPreview, CoarserLevelsForSmallViewsEachAQuarterOfTheOneBelow) {
    std::string text = "G90 G1 F1000\n";
    for (int i = 0; i < 60000; ++i) {
        const double a = i * 0.001;
        text += "X" + std::to_string(100.0 * std::cos(a)) + " Y" + std::to_string(100.0 * std::sin(a)) + "\n";
    }
    text += "M30\n";
    preview::Preview p = preview::buildPreview(m350Machine(), writeTempFile(text));
    ASSERT_TRUE(p.loaded);
    ASSERT_FALSE(p.levels.levels().empty());
    std::size_t below = p.path.size();
    double tolerance = 0.0;
    for (const auto& level : p.levels.levels()) {
        EXPECT_LE(level.size * 4, below);
        EXPECT_GT(level.tolerance, tolerance);
        below = level.size;
        tolerance = level.tolerance;
    }
    EXPECT_LT(p.levels.levels().back().size, 20000u);
    // close up every move is drawn; from far a level whose tolerance is under half a pixel
    EXPECT_EQ(p.levels.forScale(p.levels.levels().front().tolerance), nullptr);
    const auto* far = p.levels.forScale(2.0); // the 200 mm circle on 100 pixels
    ASSERT_NE(far, nullptr);
    EXPECT_LE(far->tolerance, 1.0);
    EXPECT_LT(far->size, p.path.size() / 4);
    // every kept point lies on the circle the program draws
    for (const auto& chunk : far->chunks) {
        for (const auto& point : chunk.points) {
            EXPECT_NEAR(std::hypot(point.at.x, point.at.y), 100.0, 1e-3);
        }
    }
    EXPECT_LT(p.levels.bytes(), p.path.bytes() / 2);
}

} // namespace m350::test
