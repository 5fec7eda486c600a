// Every word in the panel's language and every digit on screen: the core's alarms said by their
// message id (a crash, the E-stop) on the alarm line in zh_CN and en, the prompt drawn inside the
// window (so a screenshot shows it), a long log entry shown whole on ENTER, the machine named in
// the panel's language, and the DRO's digits fitting the controller's screen sizes.
#include "PanelHarness.h"

#include "ui/pages/LogPage.h"
#include "ui/pages/PageTable.h"
#include "ui/panel/KeyPad.h"
#include "ui/pages/MonitorPage.h"
#include "ui/pages/SystemPage.h"
#include "ui/panel/PromptBox.h"
#include "ui/widgets/DroLabel.h"

#include <QFontMetrics>
#include <QFrame>
#include <QImage>

namespace m350::test {

namespace {

void language(PanelHarness& panel, const char* name) {
    ui::OperatorAction a;
    a.kind = ui::OperatorAction::Kind::Language;
    a.name = name;
    panel.act(a);
}

// Lets the window lay itself out at a new size.
void resizeWindow(PanelHarness& panel, int width, int height) {
    panel.window().resize(width, height);
    for (int i = 0; i < 5; ++i) {
        QCoreApplication::processEvents();
    }
    panel.advance(0.1);
}

} // namespace

TEST(PanelWords, ACrashAlarmIsSaidInThePanelsLanguage) {
    ui::MachineSession::Options withTool;
    withTool.tool = 1;
    PanelHarness panel(withTool);
    language(panel, "zh_CN");
    // the drawbar released far from the rack: T1 falls onto the table
    panel.loadProgram("drop.nc", "G53 G00 X300 Y200 Z-10\nM154\nM30\n");
    panel.key("START");
    panel.advance(5.0);
    const auto alarm = panel.session().latest()->status.alarm;
    ASSERT_TRUE(alarm);
    EXPECT_EQ(alarm->code, AlarmCode::Crash);
    EXPECT_EQ(alarm->messageId, "rack_dropped");
    EXPECT_TRUE(panel.window().alarmText().endsWith(
        QStringLiteral("T1掉落：在X300.000 Y200.000 Z-10.000松刀时刀具下方没有刀位（刀具掉到工作台上）")))
        << panel.window().alarmText().toStdString();
    language(panel, "en");
    EXPECT_TRUE(panel.window().alarmText().endsWith(QStringLiteral(
        "T1 dropped: the drawbar was released at X300.000 Y200.000 Z-10.000 with no pocket under the tool (it fell "
        "onto the table)")))
        << panel.window().alarmText().toStdString();
    language(panel, "zh_CN");
}

// The parser's findings and the macro alarms are said by message id too: a program that does not
// load says why in Chinese on the message line, a division by zero on the alarm line.
TEST(PanelWords, ASyntaxErrorAndAMacroAlarmAreSaidInThePanelsLanguage) {
    PanelHarness panel;
    language(panel, "zh_CN");
    panel.loadProgram("bad.nc", "#1=1\nIF [#1 GT 0] X10\nM30\n");
    panel.advance(0.2);
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("bad.nc:2:14: IF 条件后须跟 GOTOn 或 THEN，实际为 'X'")))
        << panel.window().messageText().toStdString();
    language(panel, "en");
    panel.loadProgram("bad.nc", "#1=1\nIF [#1 GT 0] X10\nM30\n");
    panel.advance(0.2);
    EXPECT_TRUE(panel.window().messageText().contains(
        QStringLiteral("bad.nc:2:14: IF condition must be followed by GOTOn or THEN, found 'X'")))
        << panel.window().messageText().toStdString();
    language(panel, "zh_CN");
    panel.loadProgram("div.nc", "#1=0\n#2=5/#1\nM30\n");
    panel.key("START");
    panel.advance(1.0);
    const auto alarm = panel.session().latest()->status.alarm;
    ASSERT_TRUE(alarm);
    EXPECT_EQ(alarm->messageId, "division_by_zero");
    EXPECT_TRUE(panel.window().alarmText().endsWith(QStringLiteral("除数为零"))) << panel.window().alarmText().toStdString();
}

TEST(PanelWords, TheEmergencyStopIsSaidInThePanelsLanguage) {
    PanelHarness panel;
    language(panel, "zh_CN");
    panel.key("ESTOP");
    EXPECT_EQ(panel.window().alarmText(), QStringLiteral("急停：运动立即停止，输出全部关闭"));
    language(panel, "en");
    EXPECT_EQ(panel.window().alarmText(), QStringLiteral("急停 emergency stop: motion stopped at once, outputs off"));
    language(panel, "zh_CN");
}

TEST(PanelWords, AnOpenPromptIsPartOfTheWindowsImage) {
    PanelHarness panel;
    panel.key("ESTOP"); // an entry for the log, with its alarm text
    panel.key("RESET");
    panel.page(QStringLiteral("log"));
    auto* log = panel.page<ui::LogPage>();
    ASSERT_NE(log, nullptr);
    ASSERT_GT(log->rows(), 0);
    const QImage before = panel.window().grab().toImage();
    panel.key("DOWN");
    panel.key("UP"); // the newest entry
    panel.key("ENTER");
    ui::PromptBox* prompt = panel.window().prompt();
    ASSERT_TRUE(prompt->active());
    EXPECT_TRUE(prompt->question().contains(log->eventText(0))) << prompt->question().toStdString();
    // a child of the window, not a window of its own
    EXPECT_FALSE(prompt->isWindow());
    EXPECT_EQ(prompt->window(), &panel.window());
    // and in the window's grab (what m350-hmi --screenshot saves): the box's own background
    auto* frame = prompt->findChild<QFrame*>(QStringLiteral("promptFrame"));
    ASSERT_NE(frame, nullptr);
    const QImage after = panel.window().grab().toImage();
    const QPoint inside = frame->mapTo(&panel.window(), QPoint(4, 4));
    EXPECT_EQ(after.pixelColor(inside), QColor(0x1d, 0x2a, 0x44));
    EXPECT_NE(before.pixelColor(inside), after.pixelColor(inside));
    panel.key("ENTER");
    EXPECT_FALSE(prompt->active());
}

TEST(PanelWords, TheSystemPageNamesTheMachineInThePanelsLanguage) {
    PanelHarness panel;
    language(panel, "zh_CN");
    panel.page(QStringLiteral("system"));
    auto* system = panel.page<ui::SystemPage>();
    ASSERT_NE(system, nullptr);
    EXPECT_EQ(system->fieldText(QStringLiteral("machine")), QStringLiteral("M350 固定直排刀库，16个刀位，侧面装刀"));
    language(panel, "en");
    EXPECT_EQ(system->fieldText(QStringLiteral("machine")),
              QStringLiteral("M350 fixed linear rack, 16 pockets, side loading"));
    language(panel, "zh_CN");
}

// The controller's screens: every DRO coordinate shows whole (sign and every digit), and a larger
// screen shows larger digits.
TEST(PanelWords, TheDroFitsTheControllersScreenSizes) {
    PanelHarness panel;
    panel.key("MONITOR");
    auto* monitor = panel.page<ui::MonitorPage>();
    ASSERT_NE(monitor, nullptr);
    auto droPoint = [&]() {
        int point = 0;
        for (ui::DroLabel* label : monitor->findChildren<ui::DroLabel*>()) {
            if (label->isHidden()) {
                continue;
            }
            // the widest a coordinate gets, and what it shows now
            for (const QString& text : {ui::DroLabel::widestText(), label->text()}) {
                EXPECT_LE(QFontMetrics(label->font()).horizontalAdvance(text), label->contentsRect().width())
                    << label->objectName().toStdString() << " at " << panel.window().width() << "x"
                    << panel.window().height() << ": " << text.toStdString();
            }
            point = label->font().pointSize();
        }
        return point;
    };
    resizeWindow(panel, 800, 480);
    const int small = droPoint();
    resizeWindow(panel, 1024, 600);
    const int middle = droPoint();
    resizeWindow(panel, 1280, 800);
    const int large = droPoint();
    EXPECT_GT(small, 0);
    EXPECT_GT(middle, 0);
    EXPECT_GT(large, middle);
    EXPECT_GT(large, small);
}

// The controller's own screen is 800x480: the window takes that size (the key panel gives way, the
// keyboard is the panel's keys then) and no page in either language needs more room than it gets;
// from 1024x600 the key panel stands beside the screen.
TEST(PanelWords, EveryPageFitsTheControllersSmallestScreen) {
    PanelHarness panel;
    for (const char* lang : {"en", "zh_CN"}) {
        language(panel, lang);
        resizeWindow(panel, 800, 480);
        EXPECT_EQ(panel.window().size(), QSize(800, 480)) << lang;
        EXPECT_TRUE(panel.window().keyPad()->isHidden());
        for (const QString& id : ui::PageTable::ids()) {
            panel.page(id);
            QWidget* page = panel.window().currentPage();
            for (int i = 0; i < 3; ++i) {
                QCoreApplication::processEvents();
            }
            EXPECT_EQ(panel.window().size(), QSize(800, 480)) << lang << " " << id.toStdString();
            EXPECT_LE(page->minimumSizeHint().height(), page->height()) << lang << " " << id.toStdString();
            EXPECT_LE(page->minimumSizeHint().width(), page->width()) << lang << " " << id.toStdString();
        }
        // the Monitor with a program running: its window shows every row
        panel.loadProgram(QStringLiteral("fits.nc"), "G91 G1 X1 F10\nG1 X1\nG1 X1\nG1 X1\nG1 X1\nG1 X1\nM30\n");
        panel.key("MONITOR");
        panel.key("START");
        panel.advance(1.0);
        QWidget* monitor = panel.window().currentPage();
        EXPECT_EQ(panel.window().size(), QSize(800, 480)) << lang << " running";
        EXPECT_LE(monitor->minimumSizeHint().height(), monitor->height()) << lang << " running";
        panel.key("RESET");
        panel.key("PROBE");
        panel.softkey(4); // 多刀固定对刀: the tool grid takes the help text's place
        QWidget* probe = panel.window().currentPage();
        EXPECT_EQ(panel.window().size(), QSize(800, 480)) << lang << " tool grid";
        EXPECT_LE(probe->minimumSizeHint().height(), probe->height()) << lang << " tool grid";
        panel.key("ESC");
        EXPECT_EQ(panel.window().size(), QSize(800, 480)) << lang << " tool grid left";
        resizeWindow(panel, 1024, 600);
        EXPECT_EQ(panel.window().size(), QSize(1024, 600));
        EXPECT_TRUE(panel.window().keyPad()->isVisible());
    }
}

} // namespace m350::test
