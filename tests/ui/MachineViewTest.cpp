// The machine view (图形显示): opened by the Monitor's F1, it draws the loaded program's path where
// the program's moves are, colours what a run has done, names a clicked move's line, and marks an
// alarm where the spindle stood until RESET. The pixels are read from the widget as painted.
#include "PanelHarness.h"

#include "ui/pages/GraphicsPage.h"
#include "ui/pages/ProgramPage.h"
#include "ui/program/CodeView.h"
#include "ui/program/ProgramEditor.h"
#include "ui/view/MachineView.h"
#include "ui/view/PathPainter.h"
#include "ui/view/ScenePainter.h"

#include "core/preview/PreviewBuilder.h"
#include "tests/bench/MouldProgram.h"

#include <QElapsedTimer>
#include <QImage>
#include <QTest>

#include <cmath>

namespace m350 {
namespace {

using test::PanelHarness;
using ui::ViewPlane;

// Whether a pixel within `radius` of `at` has about `colour`.
bool colourNear(const QImage& image, QPointF at, const QColor& colour, int radius = 2) {
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p(int(std::lround(at.x())) + dx, int(std::lround(at.y())) + dy);
            if (!image.rect().contains(p)) {
                continue;
            }
            const QColor c = image.pixelColor(p);
            if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) + std::abs(c.blue() - colour.blue()) < 60) {
                return true;
            }
        }
    }
    return false;
}

// The widget pixel of machine X Y Z in the pane of `plane`.
QPointF pixelOf(const ui::MachineView& view, ViewPlane plane, double x, double y, double z) {
    return view.transform(plane).toPixel(ui::project(plane, x, y, z)) + QPointF(view.paneRect(plane).topLeft());
}

ui::MachineView* openGraphics(PanelHarness& panel) {
    panel.page(QStringLiteral("monitor"));
    panel.softkey(1); // 图形显示
    auto* page = panel.page<ui::GraphicsPage>();
    EXPECT_NE(page, nullptr) << "F1 opens the machine view";
    return page ? page->view() : nullptr;
}

// Loads `program`, opens the view and runs the program until it stops with its alarm.
ui::MachineView* runToAlarm(PanelHarness& panel, const QString& name, const QByteArray& program) {
    panel.loadProgram(name, program);
    ui::MachineView* view = openGraphics(panel);
    panel.key("START");
    panel.advance(10.0);
    EXPECT_TRUE(panel.session().latest()->status.alarm) << "the program should stop with an alarm";
    return view;
}

// The fault mark's ring (bright or dim: it flashes) near a pixel.
bool faultRingNear(const QImage& image, QPointF at) {
    const QColor ring(0xff, 0x30, 0x30);
    return colourNear(image, at, ring, 2) || colourNear(image, at, ring.darker(220), 2);
}

// A rectangle 100 x 50 from work zero, then up.
const QByteArray kSquare = "G90 G0 X0 Y0 Z5\nG1 Z-1 F3000\nG1 X100\nG1 Y50\nG1 X0\nG1 Y0\nG0 Z5\nM30\n";

TEST(ViewTransform, ZoomKeepsThePointUnderTheCursorAndFitShowsTheWhole) {
    ui::ViewTransform view;
    view.setSize({400, 300});
    view.fit(QRectF(0, 0, 200, 100), 0.0);
    EXPECT_DOUBLE_EQ(view.mmPerPixel(), 0.5);
    EXPECT_NEAR(view.toPixel({0, 0}).x(), 0.0, 1e-9);
    EXPECT_NEAR(view.toPixel({0, 0}).y(), 250.0, 1e-9) << "Y points up on the screen";
    EXPECT_NEAR(view.toPixel({200, 100}).y(), 50.0, 1e-9);
    const QPointF cursor(120, 80);
    const QPointF under = view.toMm(cursor);
    view.zoomAt(cursor, 3.0);
    EXPECT_NEAR(view.mmPerPixel(), 0.5 / 3.0, 1e-12);
    EXPECT_NEAR(view.toPixel(under).x(), cursor.x(), 1e-9);
    EXPECT_NEAR(view.toPixel(under).y(), cursor.y(), 1e-9);
    const QPointF before = view.toPixel({10, 10});
    view.pan({30, -20});
    EXPECT_NEAR(view.toPixel({10, 10}).x(), before.x() + 30, 1e-9);
    EXPECT_NEAR(view.toPixel({10, 10}).y(), before.y() - 20, 1e-9);
}

TEST(MachineView, F1DrawsTheLoadedProgramsPathWhereItsMovesAre) {
    PanelHarness panel;
    panel.loadProgram("square.nc", kSquare);
    ui::MachineView* view = openGraphics(panel);
    ASSERT_NE(view, nullptr);
    const auto snapshot = panel.session().latest();
    ASSERT_TRUE(snapshot->programPreview.preview) << "the preview is built when the program loads";
    const preview::Preview& built = *snapshot->programPreview.preview;
    EXPECT_EQ(built.moves, 7u);
    // the path is in machine coordinates, the program's plus the work offset, from where the
    // machine stands (machine zero here)
    const machine::Axes offset = snapshot->status.machine - snapshot->status.work;
    ASSERT_GT(offset(0), 100.0);
    const preview::Box box = built.path.bounds();
    EXPECT_NEAR(box.min.x, snapshot->status.machine(0), 1e-3);
    EXPECT_NEAR(box.max.x, offset(0) + 100.0, 1e-3);
    EXPECT_NEAR(box.max.y, offset(1) + 50.0, 1e-3);

    const QImage image = view->grab().toImage();
    const ViewPlane top = ViewPlane::Top;
    const ui::PathColours colours;
    // each side's middle is drawn in the feed colour, the middle of the rectangle is not
    for (auto [x, y] : {std::pair{50.0, 0.0}, std::pair{100.0, 25.0}, std::pair{50.0, 50.0}, std::pair{0.0, 25.0}}) {
        EXPECT_TRUE(colourNear(image, pixelOf(*view, top, offset(0) + x, offset(1) + y, 0.0), colours.feed))
            << "no feed drawn at work X" << x << " Y" << y;
    }
    EXPECT_FALSE(colourNear(image, pixelOf(*view, top, offset(0) + 50.0, offset(1) + 25.0, 0.0), colours.feed, 3));
    // the fit shows all of it: the path's box spans most of the pane, inside it
    const QPointF low = pixelOf(*view, top, box.min.x, box.min.y, 0.0);
    const QPointF high = pixelOf(*view, top, box.max.x, box.max.y, 0.0);
    const QRect pane = view->paneRect(top);
    EXPECT_TRUE(pane.contains(low.toPoint()) && pane.contains(high.toPoint()));
    EXPECT_GT(std::max(high.x() - low.x(), low.y() - high.y()), 0.6 * std::min(pane.width(), pane.height()));
    // the front view shows the plunge to Z-1
    panel.softkey(2);
    EXPECT_EQ(view->plane(), ViewPlane::Front);
    const QImage front = view->grab().toImage();
    EXPECT_TRUE(colourNear(front, pixelOf(*view, ViewPlane::Front, offset(0) + 50.0, 0.0, offset(2) - 1.0), colours.feed));
}

TEST(MachineView, WhatTheRunHasDoneTakesTheRunsColour) {
    PanelHarness panel;
    panel.loadProgram("square.nc", kSquare);
    ui::MachineView* view = openGraphics(panel);
    ASSERT_NE(view, nullptr);
    const auto before = panel.session().latest();
    const machine::Axes offset = before->status.machine - before->status.work;
    panel.key("START");
    panel.advance(60.0);
    ASSERT_EQ(panel.session().latest()->status.run, controller::PanelStatus::Run::Finished);
    EXPECT_EQ(view->content().done, 7u) << "every move of the run is done";
    const QImage image = view->grab().toImage();
    const ui::PathColours colours;
    EXPECT_TRUE(colourNear(image, pixelOf(*view, ViewPlane::Top, offset(0) + 100.0, offset(1) + 25.0, 0.0), colours.doneFeed));
    EXPECT_FALSE(colourNear(image, pixelOf(*view, ViewPlane::Top, offset(0) + 100.0, offset(1) + 25.0, 0.0), colours.feed, 1));
}

TEST(MachineView, AClickOnAMoveOpensItsLineInTheEditor) {
    PanelHarness panel;
    panel.loadProgram("square.nc", kSquare);
    ui::MachineView* view = openGraphics(panel);
    ASSERT_NE(view, nullptr);
    const auto snapshot = panel.session().latest();
    const machine::Axes offset = snapshot->status.machine - snapshot->status.work;
    // the right side, X100 from Y0 to Y50: line 4
    const QPoint at = pixelOf(*view, ViewPlane::Top, offset(0) + 100.0, offset(1) + 20.0, 0.0).toPoint();
    QTest::mouseClick(view, Qt::LeftButton, {}, at);
    QCoreApplication::processEvents();
    auto* program = panel.page<ui::ProgramPage>();
    ASSERT_NE(program, nullptr) << "the click opens the Program page";
    EXPECT_EQ(program->mode(), ui::ProgramPage::Mode::Editor);
    EXPECT_TRUE(program->editor()->path().endsWith("square.nc"));
    EXPECT_EQ(program->editor()->view()->textCursor().blockNumber() + 1, 4);
    ASSERT_TRUE(view->highlight());
    EXPECT_EQ(view->highlight()->line, 4);
}

TEST(MachineView, AnAlarmIsMarkedWhereTheSpindleStoodUntilReset) {
    PanelHarness panel;
    ui::MachineView* view = runToAlarm(panel, "alarm.nc", "G90 G0 X30 Y20\n#3000=1(BAD)\nM30\n");
    ASSERT_NE(view, nullptr);
    const auto snapshot = panel.session().latest();
    ASSERT_TRUE(snapshot->status.alarm);
    ASSERT_TRUE(view->fault());
    EXPECT_NEAR(view->fault()->at.x, snapshot->status.machine(0), 1e-6);
    EXPECT_NEAR(view->fault()->at.y, snapshot->status.machine(1), 1e-6);
    EXPECT_TRUE(view->fault()->text.contains("BAD"));
    const QImage image = view->grab().toImage();
    const QPointF at = pixelOf(*view, ViewPlane::Top, snapshot->status.machine(0), snapshot->status.machine(1), 0.0);
    EXPECT_TRUE(faultRingNear(image, at + QPointF(16, 0))) << "the marker's ring around the place";
    EXPECT_EQ(view->state()["fault"].toObject()["text"].toString(), view->fault()->text);
    panel.key("RESET");
    panel.advance(0.1);
    EXPECT_FALSE(view->fault()) << "RESET clears the mark";
}

// The rack as the parameters place it: T3 hangs in pocket 3 (params 832 / 852 / 872: X170 Y5
// Z-80); after T3 the spindle holds it and pocket 3 is empty, T1 back in pocket 1 (X50).
TEST(MachineView, TheRacksToolsAndTheSpindlesAreDrawnWhereTheParametersPutThem) {
    PanelHarness panel;
    ui::MachineView* view = openGraphics(panel);
    ASSERT_NE(view, nullptr);
    panel.softkey(2); // the front view: tools hang below their forks
    panel.softkey(3); // the path (none: the travel), then
    panel.softkey(3); // the machine
    ASSERT_TRUE(view->content().scene);
    const ViewPlane front = ViewPlane::Front;
    const QColor inPocket = ui::ScenePainter::toolInPocketColour();
    const QColor inSpindle = ui::ScenePainter::toolInSpindleColour();
    const auto toolLength = [&](int tool) { return view->content().scene->tool(tool)->length; };
    ASSERT_GT(toolLength(3), 20.0);
    const auto hangsIn = [&](double x, double z, int tool) { return pixelOf(*view, front, x, 0.0, z - toolLength(tool) / 2.0); };

    QImage image = view->grab().toImage();
    EXPECT_TRUE(colourNear(image, hangsIn(170.0, -80.0, 3), inPocket)) << "T3 in pocket 3";
    EXPECT_FALSE(colourNear(image, hangsIn(50.0, -80.0, 1), inPocket)) << "pocket 1 is empty: T1 is in the spindle";

    panel.session().runMdi({"T3"});
    panel.advance(40.0);
    const auto snapshot = panel.session().latest();
    ASSERT_EQ(snapshot->status.tool, 3);
    ASSERT_EQ(view->content().scene->spindleTool, 3);
    image = view->grab().toImage();
    EXPECT_FALSE(colourNear(image, hangsIn(170.0, -80.0, 3), inPocket)) << "pocket 3 is empty after T3";
    EXPECT_TRUE(colourNear(image, hangsIn(50.0, -80.0, 1), inPocket)) << "T1 back in pocket 1";
    const machine::Axes& nose = snapshot->status.machine;
    EXPECT_TRUE(colourNear(image, pixelOf(*view, front, nose(0), 0.0, nose(2) - toolLength(3) / 2.0), inSpindle))
        << "the spindle's tool is T3, as long as T3";
}

// T1 driven sideways into pocket 4 (X230 Y5 Z-80, holding T4): the crash alarm is marked there.
TEST(MachineView, ACrashIntoAPocketIsMarkedAtThePocket) {
    PanelHarness panel;
    ui::MachineView* view = runToAlarm(panel, "crash.nc", "G53 G0 Z0\nG53 G0 X230 Y60\nG53 G0 Z-80\nG53 G1 Y5 F2000\nM30\n");
    ASSERT_NE(view, nullptr);
    const auto snapshot = panel.session().latest();
    ASSERT_TRUE(snapshot->status.alarm);
    EXPECT_EQ(snapshot->status.alarm->code, AlarmCode::Crash);
    ASSERT_TRUE(view->fault());
    EXPECT_NEAR(view->fault()->at.x, 230.0, 1e-6);
    EXPECT_NEAR(view->fault()->at.y, 5.0, 1.0);
    EXPECT_NEAR(view->fault()->at.z, -80.0, 1e-6);
    const QImage image = view->grab().toImage();
    const QPointF at = pixelOf(*view, ViewPlane::Top, 230.0, view->fault()->at.y, -80.0);
    EXPECT_TRUE(faultRingNear(image, at + QPointF(0, -16)));
}

// A program past the preview's memory budget is drawn simplified, and the view says so.
TEST(MachineView, APathPastTheBudgetIsSimplifiedAndSaysSo) {
    auto loaded = config::loadMachineFolder(
        (std::filesystem::path(config::bundledMachinesDirectory()) / "m350-linear16").string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    QTemporaryDir dir;
    const QString path = dir.filePath("zigzag.nc");
    QByteArray text = "G90 G0 X0 Y0\n";
    for (int i = 0; i < 3000; ++i) {
        text += QByteArray("G1 X") + QByteArray::number(i % 2 ? 50 : 0) + " Y" + QByteArray::number(i * 0.01) + " F6000\n";
    }
    text += "M30\n";
    test::putFile(path, text);
    preview::PreviewSettings settings;
    settings.segmentBudget = 1000;
    auto built = std::make_shared<const preview::Preview>(
        preview::buildPreview(std::get<config::MachineConfig>(std::move(loaded)), path.toStdString(), settings));
    ASSERT_GT(built->coarsenedTo, 0.0);
    EXPECT_LE(built->path.size(), 1000u);
    EXPECT_GE(built->moves, 3001u);
    ui::MachineView view;
    view.resize(640, 400);
    ui::MachineViewContent content;
    content.preview.file = path;
    content.preview.preview = built;
    view.setContent(content);
    EXPECT_TRUE(view.notes().join(" ").contains(ui::MachineView::tr("Simplified to %1 mm (memory budget)").section('%', 0, 0)))
        << view.notes().join(" ").toStdString();
    EXPECT_GT(view.state()["path"].toObject()["coarsenedTo"].toDouble(), 0.0);
}

TEST(MachineView, KeysZoomPanAndFit) {
    PanelHarness panel;
    panel.loadProgram("square.nc", kSquare);
    ui::MachineView* view = openGraphics(panel);
    ASSERT_NE(view, nullptr);
    const double fitted = view->transform(ViewPlane::Top).mmPerPixel();
    panel.softkey(4); // zoom in
    EXPECT_NEAR(view->transform(ViewPlane::Top).mmPerPixel(), fitted / 1.5, 1e-9);
    const QPointF centre = view->transform(ViewPlane::Top).centre();
    panel.key("RIGHT");
    EXPECT_GT(view->transform(ViewPlane::Top).centre().x(), centre.x());
    panel.softkey(3); // fit: the path
    EXPECT_NEAR(view->transform(ViewPlane::Top).mmPerPixel(), fitted, 1e-9);
    EXPECT_EQ(view->state()["fit"].toString(), "path");
    const QRect pane = view->paneRect(ViewPlane::Top);
    // pocket 16 of the rack: params 845 / 865
    EXPECT_FALSE(pane.contains(pixelOf(*view, ViewPlane::Top, 950.0, 5.0, 0.0).toPoint()));
    panel.softkey(3); // again: the machine, the rack's 16 pockets over a metre of X with it
    EXPECT_EQ(view->state()["fit"].toString(), "machine");
    EXPECT_TRUE(pane.contains(pixelOf(*view, ViewPlane::Top, 950.0, 5.0, 0.0).toPoint()));
    EXPECT_GT(view->transform(ViewPlane::Top).mmPerPixel(), fitted);
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), QStringLiteral("monitor"));
}

TEST(PreviewJob, ACancelledBuildStopsSoon) {
    auto loaded = config::loadMachineFolder(
        (std::filesystem::path(config::bundledMachinesDirectory()) / "m350-linear16").string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    QTemporaryDir dir;
    const QString path = dir.filePath("endless.nc");
    test::putFile(path, "#1=0\nWHILE[#1 LT 1]DO1\nG1 X10 F60000\nG1 X0\nEND1\nM30\n");
    std::atomic<bool> cancel{false};
    preview::PreviewSettings settings;
    settings.cancel = &cancel;
    std::thread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        cancel = true;
    });
    const preview::Preview built = preview::buildPreview(std::get<config::MachineConfig>(std::move(loaded)),
                                                         path.toStdString(), settings);
    stopper.join();
    EXPECT_TRUE(built.cancelled);
    EXPECT_GT(built.moves, 0u);
}

// The preview is built beside the worker: a command given right after loading a program of a
// million lines is answered before the path is ready (the panel keeps answering keys).
TEST(PreviewJob, TheSessionAnswersWhileABigPreviewIsBuilt) {
    auto loaded = config::loadMachineFolder(
        (std::filesystem::path(config::bundledMachinesDirectory()) / "m350-linear16").string());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const std::string big = bench::program(1'000'000).path();
    ui::MachineSession session(std::get<config::MachineConfig>(std::move(loaded)), {}); // the real-time clock
    session.sync();
    QElapsedTimer clock;
    clock.start();
    session.loadProgram(QString::fromStdString(big));
    session.setJogStep(0.01);
    session.sync();
    const qint64 answered = clock.elapsed();
    QCoreApplication::processEvents();
    EXPECT_TRUE(session.latest()->programPreview.building) << "the path is not ready yet when the command is answered";
    while (!session.latest()->programPreview.preview && clock.elapsed() < 120'000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    const qint64 ready = clock.elapsed();
    ASSERT_TRUE(session.latest()->programPreview.preview) << "the preview never came";
    EXPECT_LT(answered, ready);
    EXPECT_GT(session.latest()->programPreview.preview->moves, 1'000'000u);
    EXPECT_FALSE(session.latest()->programPreview.building);
    EXPECT_DOUBLE_EQ(session.latest()->status.jogStep, 0.01);
}

} // namespace
} // namespace m350
