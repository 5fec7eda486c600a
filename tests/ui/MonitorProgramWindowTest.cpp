// Issue 25: the Monitor's program window follows the running block (its line number and text,
// highlighted) in AUTO, MDI and 试切; in 试切 the feed override shows the wheel's rate and the
// direction; a parameter params.toml does not set shows its factory value on the Param page.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/MonitorPage.h"
#include "ui/pages/ParamPage.h"
#include "ui/pages/ProgramWindow.h"

#include <cmath>

namespace m350::test {

namespace {

// Ten moves of 5 mm at 600 mm/min (0.5 s each), each line its own text.
QByteArray steps() {
    QByteArray text = "(program window)\nG91 G1 X5 F600 (step 1)\n";
    for (int step = 2; step <= 10; ++step) {
        text += QByteArray("G1 X5 (step ") + QByteArray::number(step) + ")\n";
    }
    return text + "M30\n";
}

QString lineOf(int line) { return QString::fromUtf8(steps()).split('\n').value(line - 1); }

const ui::ProgramWindow& window(PanelHarness& panel) {
    auto* monitor = panel.page<ui::MonitorPage>();
    EXPECT_NE(monitor, nullptr);
    return *monitor->programWindow();
}

int runningLine(PanelHarness& panel) { return static_cast<int>(panel.session().latest()->status.line); }

// The window shows line `line` highlighted, with its text and number, and the caption names it.
void expectShowing(PanelHarness& panel, const QString& file, int line, const QString& text) {
    const ui::ProgramWindow& w = window(panel);
    EXPECT_EQ(w.runningLine(), line);
    EXPECT_EQ(w.runningText(), text);
    EXPECT_TRUE(w.captionText().contains(file)) << w.captionText().toStdString();
    EXPECT_TRUE(w.captionText().contains(QStringLiteral("行 %1").arg(line))) << w.captionText().toStdString();
    int highlighted = 0;
    EXPECT_GT(w.rows(), ui::ProgramWindow::kRows) << "at 1024x600 the window takes the room the DRO leaves";
    for (int row = 0; row < w.rows(); ++row) {
        if (w.rowHighlighted(row)) {
            ++highlighted;
            EXPECT_EQ(w.rowText(row), QStringLiteral("%1  %2").arg(line).arg(text));
        }
    }
    EXPECT_EQ(highlighted, 1) << "one row, the running block, is highlighted";
}

} // namespace

TEST(MonitorProgramWindow, FollowsTheRunningLineInAuto) {
    PanelHarness panel;
    panel.loadProgram("steps.nc", steps());
    EXPECT_EQ(window(panel).runningLine(), 0) << "nothing runs yet";
    EXPECT_EQ(window(panel).captionText(), "steps.nc");
    EXPECT_EQ(window(panel).rowText(0), "1  (program window)") << "the top of the loaded program";

    panel.key("START");
    panel.advance(1.2);
    const int first = runningLine(panel);
    ASSERT_GE(first, 3);
    expectShowing(panel, "steps.nc", first, lineOf(first));

    panel.advance(1.5);
    const int later = runningLine(panel);
    ASSERT_GT(later, first) << "the run went on";
    expectShowing(panel, "steps.nc", later, lineOf(later));

    panel.advance(10.0);
    EXPECT_EQ(window(panel).runningLine(), 0) << "the run is over: no block is highlighted";
}

TEST(MonitorProgramWindow, ShowsTheMdiLineItRuns) {
    PanelHarness panel;
    panel.key("MDI");
    panel.type("G91 G1 X50 F600");
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(0.5);
    panel.key("MONITOR");
    ASSERT_GT(runningLine(panel), 0);
    expectShowing(panel, "mdi.nc", runningLine(panel), "G91 G1 X50 F600");
}

TEST(MonitorProgramWindow, FollowsTheHandwheelGuidedRunAndShowsTheWheelsOverride) {
    PanelHarness panel;
    panel.loadProgram("steps.nc", steps());
    panel.key("MPG_RUN");
    panel.key("START");
    panel.turnWheel(0, 10, 2, 0.3); // two detents a frame at x10: the override ramps up (param 180)
    auto* monitor = panel.page<ui::MonitorPage>();
    ASSERT_NE(monitor, nullptr);
    const controller::PanelStatus& s = panel.session().latest()->status;
    ASSERT_TRUE(s.guide);
    ASSERT_GT(s.line, 0u);
    expectShowing(panel, "steps.nc", runningLine(panel), lineOf(runningLine(panel)));

    const QString fro = monitor->infoText("fro");
    EXPECT_EQ(fro, QStringLiteral("%1%  顺切").arg(std::round(s.guideOverride))) << fro.toStdString();
    EXPECT_GT(s.guideOverride, 5.0);
    EXPECT_LT(s.guideOverride, 95.0) << "mid-ramp: the wheel, not the FRO key (100 %), sets the rate";

    const int before = runningLine(panel);
    panel.turnWheel(0, 10, 2, 3.0);
    EXPECT_GT(runningLine(panel), before) << "the wheel drives the program on";
    expectShowing(panel, "steps.nc", runningLine(panel), lineOf(runningLine(panel)));
}

TEST(ParamPageFactoryValues, AParameterTheFolderDoesNotSetShowsItsFactoryValue) {
    PanelHarness panel;
    ASSERT_FALSE(fileText(panel.folder() + "/params.toml").contains(QRegularExpression("(?m)^\\s*172\\s*=")))
        << "the bundled machine leaves 172 to its factory value";
    panel.key("PARAM");
    auto* page = panel.page<ui::ParamPage>();
    ASSERT_NE(page, nullptr);
    panel.softkey(2); // 搜索
    panel.type("172");
    panel.key("ENTER");
    ASSERT_EQ(page->selectedNumber(), 172);
    EXPECT_EQ(page->state()["param_value"].toString(), "0.004") << "手轮X1距离: 0.004 mm per detent";
    panel.softkey(2);
    panel.type("176");
    panel.key("ENTER");
    ASSERT_EQ(page->selectedNumber(), 176);
    EXPECT_EQ(page->state()["param_value"].toString(), "20.000") << "the wheel's x1 speed, mm/min";
}

} // namespace m350::test
