// The operator's hands: the PC keyboard, clicks on the panel's keys, and the handwheel turned by
// the mouse wheel, all reaching the machine through the one dispatcher.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/MonitorPage.h"
#include "ui/panel/HandwheelWidget.h"
#include "ui/panel/KeyPad.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/panel/StatusLine.h"

#include <QFile>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

namespace m350::test {

namespace {

double machineX(PanelHarness& panel) { return panel.session().latest()->status.machine(0); }

} // namespace

TEST(PanelInput, TheF4KeyIsTheFourthSoftkey) {
    PanelHarness panel;
    QTest::keyClick(&panel.window(), Qt::Key_F4);
    ui::settle(panel.session());
    EXPECT_EQ(panel.page<ui::MonitorPage>()->menu(), ui::MonitorPage::Menu::GoHome);
    QTest::keyClick(&panel.window(), Qt::Key_Escape);
    EXPECT_EQ(panel.page<ui::MonitorPage>()->menu(), ui::MonitorPage::Menu::Main);
}

TEST(PanelInput, CtrlArrowJogsWhileHeldAndStopsOnRelease) {
    PanelHarness panel;
    const double start = machineX(panel);
    QTest::keyPress(&panel.window(), Qt::Key_Right, Qt::ControlModifier);
    panel.advance(1.0);
    const double held = machineX(panel);
    EXPECT_GT(held, start + 1.0) << "X+ moves while the key is held";
    EXPECT_TRUE(panel.session().latest()->status.jogging);
    QTest::keyRelease(&panel.window(), Qt::Key_Right, Qt::ControlModifier);
    panel.advance(2.0);
    const double rest = machineX(panel);
    panel.advance(1.0);
    EXPECT_DOUBLE_EQ(machineX(panel), rest) << "at rest after the release";
    EXPECT_FALSE(panel.session().latest()->status.jogging);
}

TEST(PanelInput, ClickingTheOnScreenStartKeyRunsTheLoadedProgram) {
    PanelHarness panel;
    panel.loadProgram("part.nc", "G90 G0 X12.5\nM30\n");
    QTest::mouseClick(panel.window().keyPad()->button("START"), Qt::LeftButton);
    ui::settle(panel.session());
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("自动"));
    panel.advance(5.0);
    EXPECT_EQ(panel.page<ui::MonitorPage>()->workText(0), "12.500");
}

TEST(PanelInput, TheMouseWheelTurnsTheHandwheelInMpgMode) {
    PanelHarness panel;
    // param 171 = 0: every pulse runs out (its factory 1 stops the axis with the wheel: ManualJogTest)
    panel.session().setParameter(171, 0.0);
    ui::settle(panel.session());
    panel.key("CONT_STEP_MPG");
    panel.key("CONT_STEP_MPG");
    ASSERT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("手轮"));
    ui::HandwheelWidget* wheel = panel.window().keyPad()->handwheel();
    QTest::mouseClick(wheel->findChild<QPushButton*>("wheelStep100"), Qt::LeftButton);
    const double start = machineX(panel);
    QPointF centre(wheel->width() / 2.0, wheel->height() - 40.0);
    for (int notch = 0; notch < 5; ++notch) {
        QWheelEvent event(centre, wheel->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(wheel, &event);
    }
    QTest::qWait(120); // the wheel sends what it gathered every 50 ms
    panel.advance(3.0);
    // 5 detents x100 x param 172, which the default machine leaves to its factory value, 0.004 mm
    ASSERT_EQ(panel.session().latest()->status.parameters.get(172), 0.004);
    EXPECT_NEAR(machineX(panel) - start, 5 * 100 * 0.004, 1e-6);
}

TEST(PanelInput, OverrideKeysStepTheFeedOverride) {
    PanelHarness panel;
    panel.key("FRO_UP");
    panel.key("FRO_UP");
    EXPECT_EQ(panel.page<ui::MonitorPage>()->infoText("fro"), "120%");
    panel.key("FRO_DOWN");
    EXPECT_EQ(panel.page<ui::MonitorPage>()->infoText("fro"), "110%");
    panel.key("FRO_100");
    EXPECT_EQ(panel.page<ui::MonitorPage>()->infoText("fro"), "100%");
    panel.key("SRO_DOWN");
    EXPECT_EQ(panel.page<ui::MonitorPage>()->infoText("sro"), "90%");
}

TEST(PanelInput, SpindleKeysTurnTheSpindleAndTheMonitorSaysSo) {
    PanelHarness panel;
    panel.key("M3");
    panel.advance(3.0);
    EXPECT_TRUE(panel.page<ui::MonitorPage>()->infoText("spindle").contains(QStringLiteral("正转")))
        << panel.page<ui::MonitorPage>()->infoText("spindle").toStdString();
    panel.key("M5");
    panel.advance(5.0);
    EXPECT_TRUE(panel.page<ui::MonitorPage>()->infoText("spindle").contains(QStringLiteral("停止")));
}

TEST(PanelInput, EstopAlarmsAndResetClearsIt) {
    PanelHarness panel;
    panel.key("ESTOP");
    EXPECT_EQ(panel.window().statusLine()->stateText(), QStringLiteral("警告"));
    EXPECT_FALSE(panel.window().alarmText().isEmpty());
    panel.key("RESET");
    EXPECT_EQ(panel.window().statusLine()->stateText(), QStringLiteral("就绪"));
    EXPECT_TRUE(panel.window().alarmText().isEmpty());
}

} // namespace m350::test
