// 对刀 on the Probe page through the operator's keys, on a copy of the default machine with its own
// hooks and slib-probe.nc: the multi-tool setting, XY/Z teach and an alarm that stops a setting.
// What a setting writes into parameters is in params.toml once the run stops, as on the controller.
#include "PanelHarness.h"

#include "ui/pages/ProbePage.h"
#include "ui/panel/PromptBox.h"
#include "ui/panel/StatusLine.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

namespace m350::test {

namespace {

QString paramsFile(PanelHarness& panel) {
    QFile file(QDir(panel.folder()).filePath("params.toml"));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    return QString::fromUtf8(file.readAll());
}

double parameter(PanelHarness& panel, int number) { return panel.session().latest()->status.parameters.get(number); }

} // namespace

TEST(ProbeWorkflow, MultiToolSettingSetsTheChosenToolsAndKeepsThem) {
    PanelHarness panel;
    panel.session().setParameter(935, 0); // T6 not set yet
    panel.key("PROBE");
    auto* probe = panel.page<ui::ProbePage>();
    panel.softkey(4); // 多刀固定对刀: the T1-T16 grid
    for (int step = 0; step < 5; ++step) {
        panel.key("RIGHT");
    }
    panel.key("ENTER"); // T6
    panel.key("DOWN");
    panel.key("ENTER"); // T14
    panel.softkey(4);   // 是否将选中的刀具进行一键对刀操作?
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ENTER");
    panel.advance(2.0);
    EXPECT_TRUE(probe->progressText().contains(QStringLiteral("多刀对刀 T6: 1/2"))) << probe->progressText().toStdString();
    panel.advance(120.0);
    // T6 is 70.25 long, T14 69.0; the setter's top is at -120
    EXPECT_NEAR(parameter(panel, 935), -49.75, 1e-9);
    EXPECT_NEAR(parameter(panel, 943), -51.0, 1e-9);
    EXPECT_TRUE(probe->offsetText(6).contains("-49.750")) << probe->offsetText(6).toStdString();
    EXPECT_EQ(panel.session().latest()->status.tool, 14);
    const QString params = paramsFile(panel);
    EXPECT_TRUE(params.contains(QStringLiteral("935 = -49.75"))) << params.toStdString();
    EXPECT_TRUE(params.contains(QStringLiteral("943 = -51"))) << params.toStdString();
}

TEST(ProbeWorkflow, WithAToolTableTheSettingGoesIntoToolTblToo) {
    QTemporaryDir dir;
    QString error;
    auto copy = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(copy) << error.toStdString();
    const QString folder = *copy;
    QFile table(QDir(folder).filePath("tool.tbl"));
    ASSERT_TRUE(table.open(QIODevice::WriteOnly | QIODevice::Truncate));
    table.write("T1 P1 Z-50.000000 D6.000000 ;6 mm end mill\n");
    table.close();
    PanelHarness panel(folder); // the panel started again: T1's Z comes from tool.tbl
    EXPECT_NEAR(parameter(panel, 930), -50.0, 1e-9);
    panel.key("PROBE");
    panel.softkey(3); // 固定对刀 T1
    panel.key("ENTER");
    panel.key("ESC"); // only the tool's Z offset
    panel.advance(60.0);
    EXPECT_NEAR(parameter(panel, 930), -53.677, 1e-9);
    ASSERT_TRUE(table.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(table.readAll());
    EXPECT_TRUE(text.contains(QStringLiteral("Z-53.677"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral(";6 mm end mill"))) << text.toStdString();
    EXPECT_TRUE(paramsFile(panel).contains(QStringLiteral("930 = -53.677")));
}

TEST(ProbeWorkflow, TeachRunsTheMacroAndTheSetterPositionStays) {
    PanelHarness panel;
    panel.session().runMdi({QStringLiteral("G53 X512.5 Y70.25 Z-44.5")}, ui::Activity::Mdi);
    panel.advance(10.0);
    panel.key("PROBE");
    auto* probe = panel.page<ui::ProbePage>();
    panel.softkey(5); // XY位置教导: (XY)当前机械坐标是否为对刀仪XY坐标?
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ENTER");
    panel.advance(1.0);
    EXPECT_EQ(probe->fieldText("x"), QStringLiteral("512.500"));
    EXPECT_EQ(probe->fieldText("y"), QStringLiteral("70.250"));
    EXPECT_EQ(probe->fieldText("z"), QStringLiteral("-30.000")); // not taught
    panel.softkey(6);                                            // Z位置教导
    panel.key("ENTER");
    panel.advance(1.0);
    EXPECT_EQ(probe->fieldText("z"), QStringLiteral("-44.500"));
    const QString params = paramsFile(panel);
    for (const char* line : {"135 = 512.5", "136 = 70.25", "137 = -44.5"}) {
        EXPECT_TRUE(params.contains(QLatin1String(line))) << line << "\n" << params.toStdString();
    }
}

TEST(ProbeWorkflow, ASetterThatNeverTripsStopsTheSettingWithAnAlarm) {
    PanelHarness panel;
    panel.session().forceInput(12, ui::MachineSession::Fault::Stuck, 0, 0.0); // IN12's cable broken
    panel.key("PROBE");
    panel.softkey(3); // 固定对刀, T1 (in the spindle)
    panel.key("ENTER");
    ASSERT_TRUE(panel.window().prompt()->active()); // Z轴工件原点是否已确定?
    panel.key("ESC");
    panel.advance(60.0);
    EXPECT_TRUE(panel.window().alarmText().contains("IN12")) << panel.window().alarmText().toStdString();
    EXPECT_EQ(panel.window().statusLine()->stateText(), QStringLiteral("故障"));
    EXPECT_NEAR(parameter(panel, 930), -53.677, 1e-9); // T1 keeps its offset
}

} // namespace m350::test
