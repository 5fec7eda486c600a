// The axes a machine has, on every screen that shows axes: the DRO (机械坐标, 工件坐标), the jog
// keys and the wheel, 坐标管理 and 对刀, on machine folders whose parameters give a 4th and 5th
// axis (an owner's dual-Y gantry with a rotary B, a rotary 4th called C) and on the bundled 3-axis
// machines, driven through the operator's path and read off the widgets.
#include "tests/ui/PanelHarness.h"

#include "core/config/MachineConfig.h"
#include "ui/pages/CompactDro.h"
#include "ui/pages/CoordPage.h"
#include "ui/pages/MonitorPage.h"
#include "ui/pages/ProbePage.h"
#include "ui/panel/HandwheelWidget.h"
#include "ui/panel/KeyPad.h"
#include "ui/panel/PromptBox.h"
#include "ui/panel/SoftkeyBar.h"

#include <QPushButton>
#include <QTemporaryDir>

#include <filesystem>

namespace m350::test {

namespace {

namespace fs = std::filesystem;

// The bundled machines copied whole into `dir` (the M350 folders share m350-linear16's libraries),
// `extra` parameter lines added to `name`'s params.toml, whose only table is [params]. Returns the
// copy of `name`.
QString machinesCopy(const QTemporaryDir& dir, const QString& name, const QByteArray& extra = {}) {
    const fs::path to = fs::path(dir.path().toStdString()) / "machines";
    fs::copy(config::bundledMachinesDirectory(), to, fs::copy_options::recursive);
    const QString folder = QString::fromStdString((to / name.toStdString()).string());
    if (!extra.isEmpty()) {
        const QString params = QDir(folder).filePath("params.toml");
        putFile(params, fileText(params).toUtf8() + "\n" + extra);
    }
    return folder;
}

// An owner's router (the DDCS-Expert skill's Ultimate Bee): drive 4 is the gantry's second Y motor,
// drive 5 a rotary axis named B; the 4th axis A is linear.
// (m350-linear16's params.toml already has 125/126 = 0: the 4th and 5th stand at 0 after homing.)
const QByteArray kOwnersGantry = "488 = 0\n489 = 1\n490 = 2\n491 = 1\n492 = 4\n"
                                 "443 = 3\n444 = 4\n449 = 0\n450 = 1\n";

// A rotary 4th axis on drive 4, named C.
const QByteArray kRotaryC = "491 = 3\n443 = 5\n449 = 1\n";

QPushButton* keyButton(PanelHarness& panel, const QString& name) { return panel.window().keyPad()->button(name); }

QPushButton* wheelAxis(PanelHarness& panel, int axis) {
    return panel.window().keyPad()->handwheel()->findChild<QPushButton*>(QStringLiteral("wheelAxis%1").arg(axis));
}

double machine(PanelHarness& panel, int axis) { return panel.session().latest()->status.machine(axis); }

void setLanguage(PanelHarness& panel, const char* name) {
    ui::OperatorAction a;
    a.kind = ui::OperatorAction::Kind::Language;
    a.name = QString::fromLatin1(name);
    panel.act(a);
}

} // namespace

TEST(Axes, TheOwnersGantryShowsAAndBOnTheMonitorWithTheirUnits) {
    QTemporaryDir dir;
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kOwnersGantry));
    auto* monitor = panel.page<ui::MonitorPage>();
    ASSERT_NE(monitor, nullptr);
    for (int axis = 0; axis < 5; ++axis) {
        EXPECT_TRUE(monitor->axisVisible(axis)) << axis;
    }
    EXPECT_TRUE(monitor->axisText(3).startsWith(QStringLiteral("A "))) << monitor->axisText(3).toStdString();
    EXPECT_TRUE(monitor->axisText(4).startsWith(QStringLiteral("B "))) << monitor->axisText(4).toStdString();
    EXPECT_EQ(monitor->unitText(0), QStringLiteral("mm"));
    EXPECT_EQ(monitor->unitText(3), QStringLiteral("mm")) << "the gantry's A is linear (param 449 = 0)";
    EXPECT_EQ(monitor->unitText(4), QStringLiteral("度")) << "B turns (param 450 = 1)";
    EXPECT_EQ(monitor->machineText(3), QStringLiteral("0.000"));
    EXPECT_EQ(monitor->workText(4), QStringLiteral("0.000"));
    setLanguage(panel, "en");
    EXPECT_EQ(monitor->unitText(4), QStringLiteral("deg"));

    // the Go Home row names them too, and lets them be homed
    setLanguage(panel, "zh_CN");
    panel.key("F4");
    EXPECT_EQ(panel.window().softkeys()->label(4), QStringLiteral("F4 机械A轴回"));
    EXPECT_TRUE(panel.window().softkeys()->enabled(4));
    EXPECT_EQ(panel.window().softkeys()->label(5), QStringLiteral("F5 机械B轴回"));
    EXPECT_TRUE(panel.window().softkeys()->enabled(5));
}

TEST(Axes, TheFourthAndFifthJogKeysMoveAAndB) {
    QTemporaryDir dir;
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kOwnersGantry));
    auto* monitor = panel.page<ui::MonitorPage>();
    for (const char* name : {"JOG_A+", "JOG_A-", "JOG_B+", "JOG_B-"}) {
        ASSERT_NE(keyButton(panel, name), nullptr) << name;
        EXPECT_TRUE(keyButton(panel, name)->isEnabled()) << name;
    }
    EXPECT_EQ(keyButton(panel, "JOG_A+")->text(), QStringLiteral("A+"));
    EXPECT_EQ(keyButton(panel, "JOG_B-")->text(), QStringLiteral("B-"));

    panel.key("CONT_STEP_MPG"); // 寸动
    panel.key("STEP_1");
    const double y = machine(panel, 1);
    panel.key("JOG_A+");
    panel.advance(2.0);
    EXPECT_EQ(monitor->machineText(3), QStringLiteral("1.000"));
    EXPECT_EQ(monitor->workText(3), QStringLiteral("1.000"));
    panel.key("JOG_B-");
    panel.key("JOG_B-");
    panel.advance(2.0);
    EXPECT_EQ(monitor->machineText(4), QStringLiteral("-2.000"));
    EXPECT_DOUBLE_EQ(machine(panel, 1), y) << "A is an axis of its own: Y stays";

    // held in CONT, A moves until the key comes up
    panel.key("CONT_STEP_MPG");
    panel.key("CONT_STEP_MPG"); // 手轮, then 连续 again
    const double a = machine(panel, 3);
    panel.act(ui::OperatorAction::keyDown("JOG_A-"));
    panel.advance(1.0);
    panel.act(ui::OperatorAction::keyUp("JOG_A-"));
    panel.advance(2.0);
    EXPECT_LT(machine(panel, 3), a - 1.0);
    EXPECT_FALSE(panel.session().latest()->status.jogging);
}

TEST(Axes, TheWheelTurnsBWhenItsAxisSwitchSaysB) {
    QTemporaryDir dir;
    // 171 = 0: every pulse of the turn runs out (its factory 1 stops the axis with the wheel)
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kOwnersGantry + "171 = 0\n"));
    ASSERT_TRUE(wheelAxis(panel, 4)->isEnabled());
    EXPECT_EQ(wheelAxis(panel, 3)->text(), QStringLiteral("A"));
    EXPECT_EQ(wheelAxis(panel, 4)->text(), QStringLiteral("B"));
    panel.key("CONT_STEP_MPG");
    panel.key("CONT_STEP_MPG"); // 手轮
    panel.turnWheel(4, 100, 1, 0.5);
    panel.advance(2.0);
    EXPECT_GT(machine(panel, 4), 0.5);
    EXPECT_DOUBLE_EQ(machine(panel, 3), 0.0);
}

TEST(Axes, CoordSetShowsAAndBAndSetsAsWorkCoordinate) {
    QTemporaryDir dir;
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kOwnersGantry));
    panel.softkey(8); // 坐标管理
    auto* coord = panel.page<ui::CoordPage>();
    ASSERT_NE(coord, nullptr);
    EXPECT_EQ(coord->columnText(0), QStringLiteral("X (mm)"));
    EXPECT_EQ(coord->columnText(3), QStringLiteral("A (mm)"));
    EXPECT_EQ(coord->columnText(4), QStringLiteral("B (度)"));
    EXPECT_TRUE(coord->columnShown(3));
    EXPECT_TRUE(coord->columnShown(4));
    EXPECT_EQ(panel.window().softkeys()->label(8), QStringLiteral("\u21e7F2 设置A"));
    EXPECT_EQ(panel.window().softkeys()->label(9), QStringLiteral("\u21e7F3 设置B"));
    EXPECT_TRUE(panel.window().softkeys()->enabled(8));

    panel.softkey(8); // 设置A
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().prompt()->question().startsWith(QStringLiteral("A"))) <<
        panel.window().prompt()->question().toStdString();
    panel.key("BACKSPACE");
    panel.type("12.5");
    panel.key("ENTER");
    EXPECT_NEAR(panel.session().latest()->status.work(3), 12.5, 1e-9);
    EXPECT_EQ(coord->offsetText(1, 3), QString::number(machine(panel, 3) - 12.5, 'f', 3));
    panel.key("ESC");
    EXPECT_EQ(panel.page<ui::MonitorPage>()->workText(3), QStringLiteral("12.500"));
}

TEST(Axes, TheProbePageShowsAAndB) {
    QTemporaryDir dir;
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kOwnersGantry));
    panel.softkey(2); // 对刀
    auto* probe = panel.page<ui::ProbePage>();
    ASSERT_NE(probe, nullptr);
    const ui::CompactDro* dro = probe->dro();
    EXPECT_TRUE(dro->axisVisible(3));
    EXPECT_TRUE(dro->axisVisible(4));
    EXPECT_EQ(dro->axisText(3), QStringLiteral("A"));
    EXPECT_EQ(dro->axisText(4), QStringLiteral("B"));
    EXPECT_EQ(dro->unitText(3), QStringLiteral("mm"));
    EXPECT_EQ(dro->unitText(4), QStringLiteral("度"));
}

TEST(Axes, ARotaryFourthCalledCIsCEverywhere) {
    QTemporaryDir dir;
    PanelHarness panel(machinesCopy(dir, "m350-linear16", kRotaryC));
    auto* monitor = panel.page<ui::MonitorPage>();
    EXPECT_TRUE(monitor->axisText(3).startsWith(QStringLiteral("C "))) << monitor->axisText(3).toStdString();
    EXPECT_EQ(monitor->unitText(3), QStringLiteral("度"));
    EXPECT_FALSE(monitor->axisVisible(4)) << "no drive reaches a 5th axis";
    EXPECT_EQ(keyButton(panel, "JOG_A+")->text(), QStringLiteral("C+"));
    EXPECT_FALSE(keyButton(panel, "JOG_B+")->isEnabled());
    panel.key("F5"); // 清零
    EXPECT_EQ(panel.window().softkeys()->label(4), QStringLiteral("F4 C清零"));
    EXPECT_FALSE(panel.window().softkeys()->enabled(5));

    panel.key("ESC");
    panel.key("CONT_STEP_MPG");
    panel.key("STEP_1");
    panel.key("JOG_A-");
    panel.advance(2.0);
    EXPECT_EQ(monitor->machineText(3), QStringLiteral("-1.000"));
}

// Every bundled machine (M350 and FANUC) has X Y Z only: no 4th or 5th row, column or key, and
// a 4th-axis jog from the keyboard or a replay moves nothing.
TEST(Axes, TheBundledMachinesShowExactlyXYZ) {
    QTemporaryDir dir;
    const QString machines = QFileInfo(machinesCopy(dir, "m350-linear16")).path();
    const QStringList names = QDir(machines).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    ASSERT_GE(names.size(), 9);
    for (const QString& name : names) {
        SCOPED_TRACE(name.toStdString());
        PanelHarness panel(QDir(machines).filePath(name));
        auto* monitor = panel.page<ui::MonitorPage>();
        ASSERT_NE(monitor, nullptr);
        for (int axis = 0; axis < 5; ++axis) {
            EXPECT_EQ(monitor->axisVisible(axis), axis < 3) << axis;
        }
        EXPECT_TRUE(monitor->axisText(2).startsWith(QStringLiteral("Z ")));
        for (const char* key : {"JOG_A+", "JOG_A-", "JOG_B+", "JOG_B-"}) {
            EXPECT_FALSE(keyButton(panel, key)->isEnabled()) << key;
        }
        EXPECT_EQ(keyButton(panel, "JOG_A+")->text(), QStringLiteral("4th+"));
        EXPECT_FALSE(wheelAxis(panel, 3)->isEnabled());
        panel.key("MONITOR");
        panel.softkey(8); // 坐标管理
        auto* coord = panel.page<ui::CoordPage>();
        ASSERT_NE(coord, nullptr);
        EXPECT_TRUE(coord->columnShown(2));
        EXPECT_FALSE(coord->columnShown(3));
        EXPECT_FALSE(coord->columnShown(4));
        EXPECT_FALSE(panel.window().softkeys()->enabled(8));

        panel.key("CONT_STEP_MPG");
        panel.key("STEP_1");
        // where the absent axes stand (their params 125/126 at the factory's 5 and 40, or 0)
        const double a = machine(panel, 3);
        const double b = machine(panel, 4);
        panel.key("JOG_A+");
        panel.act(ui::OperatorAction::keyDown("JOG_B+"));
        panel.advance(1.0);
        panel.act(ui::OperatorAction::keyUp("JOG_B+"));
        EXPECT_DOUBLE_EQ(machine(panel, 3), a);
        EXPECT_DOUBLE_EQ(machine(panel, 4), b);
    }
}

} // namespace m350::test
