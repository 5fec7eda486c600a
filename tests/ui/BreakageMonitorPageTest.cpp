// 破损监测 as an operator reaches it: 对刀, F2 刀具表, Shift+F2; the page reads the spindle load of
// the cut on the fanuc-ts27r machine from the session's snapshot, with T1's limits, and shows the
// monitor's alarm when T1 breaks in the cut.
#include "tests/ui/PanelHarness.h"

#include "core/config/MachineConfig.h"
#include "ui/pages/BreakageMonitorPage.h"

#include <QChart>
#include <QChartView>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QValueAxis>

#include <cmath>
#include <filesystem>

namespace m350::test {

namespace {

const char* kCut = "G90 G49\nS6000 M03\nG00 X-150 Y0\nG00 Z-355\nG01 Z-362 F300\nG01 X150 F600\nG00 Z0\nM05\nM30\n";

// A copy of the bundled fanuc-ts27r in `dir`, with the cut program beside it.
QString ts27rCopy(const QTemporaryDir& dir) {
    namespace fs = std::filesystem;
    fs::path to = fs::path(dir.path().toStdString()) / "fanuc-ts27r";
    fs::copy(config::bundledMachinesDirectory() + "/fanuc-ts27r", to, fs::copy_options::recursive);
    QFile program(QString::fromStdString((to / "cut.nc").string()));
    EXPECT_TRUE(program.open(QIODevice::WriteOnly));
    program.write(kCut);
    return QString::fromStdString(to.string());
}

void loadCut(PanelHarness& panel) {
    QString error;
    auto action = ui::OperatorAction::fromJson(
        QJsonObject{{"t", 0}, {"load", QDir(panel.folder()).filePath("cut.nc")}}, &error);
    ASSERT_TRUE(action) << error.toStdString();
    panel.act(*action);
}

ui::BreakageMonitorPage* openMonitor(PanelHarness& panel) {
    panel.key("PROBE");
    panel.softkey(2);  // 刀具表
    panel.softkey(8);  // Shift+F2 破损监测
    return panel.page<ui::BreakageMonitorPage>();
}

ui::MachineSession::Options withTool1(std::vector<machine::ToolBreak> breaks = {}) {
    ui::MachineSession::Options options;
    options.tool = 1;
    options.toolBreaks = std::move(breaks);
    return options;
}

} // namespace

TEST(BreakageMonitorPage, TheToolTablesShiftF2OpensItAndItPlotsTheCutsLoadWithT1sLimits) {
    QTemporaryDir dir;
    PanelHarness panel(ts27rCopy(dir), withTool1());
    loadCut(panel);
    panel.key("START");
    panel.advance(10.0);
    ui::BreakageMonitorPage* page = openMonitor(panel);
    ASSERT_NE(page, nullptr) << "刀具表's Shift+F2";
    EXPECT_EQ(page->fieldText("tool"), QStringLiteral("T1"));
    EXPECT_EQ(page->fieldText("load"), QStringLiteral("33.29 %")) << "6000 rpm, 600 mm/min, 2 x 10 mm";
    EXPECT_EQ(page->fieldText("register"), QStringLiteral("#1032 = 3329"));
    EXPECT_EQ(page->fieldText("lambda"), QStringLiteral("143"));
    EXPECT_EQ(page->limitLines(), qMakePair(10.0, 60.0));
    EXPECT_GT(page->plottedPoints(), 50);
    EXPECT_EQ(page->fieldText("alarm"), ui::BreakageMonitorPage::tr("None"));
    const auto& view = *panel.session().latest()->spindleLoad;
    EXPECT_EQ(page->plottedPoints(), static_cast<int>(view.points.size())) << "every point the core gave";
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), QStringLiteral("tools"));
}

TEST(BreakageMonitorPage, ABreakInTheCutShowsTheMonitorsAlarmAndTheIdleLoad) {
    QTemporaryDir dir;
    PanelHarness panel(ts27rCopy(dir), withTool1({{1, 0.62, 12.05}}));
    loadCut(panel);
    ui::BreakageMonitorPage* page = openMonitor(panel);
    ASSERT_NE(page, nullptr);
    panel.key("START");
    panel.advance(14.0);
    const auto& status = panel.session().latest()->status;
    ASSERT_TRUE(status.alarm);
    EXPECT_EQ(status.alarm->code, AlarmCode::SpindleLoad);
    EXPECT_TRUE(page->fieldText("alarm").contains(QStringLiteral("now 3.29 % (below)"))) << page->fieldText("alarm").toStdString();
    EXPECT_EQ(page->fieldText("load"), QStringLiteral("3.29 %"));
}

TEST(BreakageMonitorPage, AMachineWithoutALoadModelSaysSo) {
    PanelHarness panel;
    ui::BreakageMonitorPage* page = openMonitor(panel);
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(page->plottedPoints(), 0);
    EXPECT_TRUE(page->fieldText("rule").contains(QStringLiteral("[spindle_load]"))) << page->fieldText("rule").toStdString();
    EXPECT_TRUE(std::isnan(page->limitLines().first));
}

// With nothing plotted the axes still read as an operator expects: 0-30 s every 5 s, 0-100 %
// every 20 %, labels on round numbers.
TEST(BreakageMonitorPage, AnEmptyChartHasRoundTicks) {
    PanelHarness panel;
    ui::BreakageMonitorPage* page = openMonitor(panel);
    ASSERT_NE(page, nullptr);
    auto* view = page->findChild<QChartView*>(QStringLiteral("breakageChart"));
    ASSERT_NE(view, nullptr);
    auto* time = qobject_cast<QValueAxis*>(view->chart()->axes(Qt::Horizontal).value(0));
    auto* load = qobject_cast<QValueAxis*>(view->chart()->axes(Qt::Vertical).value(0));
    ASSERT_TRUE(time && load);
    EXPECT_EQ(time->min(), 0.0);
    EXPECT_EQ(time->max(), 30.0);
    EXPECT_EQ(time->tickType(), QValueAxis::TicksDynamic);
    EXPECT_EQ(time->tickAnchor(), 0.0);
    EXPECT_EQ(time->tickInterval(), 5.0);
    EXPECT_EQ(load->min(), 0.0);
    EXPECT_EQ(load->max(), 100.0);
    EXPECT_EQ(load->tickInterval(), 20.0);
}

} // namespace m350::test
