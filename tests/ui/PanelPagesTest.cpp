// The Monitor, MDI, IO and Probe screens, driven as an operator drives them and read off the widgets.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/IoPage.h"
#include "core/controller/ParameterWrites.h"
#include "ui/pages/MdiPage.h"
#include "ui/pages/MonitorPage.h"
#include "ui/pages/ProbePage.h"
#include "ui/panel/PromptBox.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/panel/StatusLine.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

namespace m350::test {

using ui::OperatorAction;

TEST(MonitorPage, GoHomeSoftkeyOpensItsRowAndEscGoesBack) {
    PanelHarness panel;
    ASSERT_EQ(panel.window().currentPage()->id(), "monitor");
    EXPECT_TRUE(panel.window().softkeys()->label(4).contains(QStringLiteral("回机械原点")));
    panel.key("F4");
    auto* monitor = panel.page<ui::MonitorPage>();
    ASSERT_NE(monitor, nullptr);
    EXPECT_EQ(monitor->menu(), ui::MonitorPage::Menu::GoHome);
    EXPECT_TRUE(panel.window().softkeys()->label(1).contains(QStringLiteral("机械X轴回")));
    EXPECT_TRUE(panel.window().softkeys()->label(6).contains(QStringLiteral("机械全部回")));
    panel.key("ESC");
    EXPECT_EQ(monitor->menu(), ui::MonitorPage::Menu::Main);
    EXPECT_TRUE(panel.window().softkeys()->label(5).contains(QStringLiteral("清零")));
}

TEST(MonitorPage, UnsimulatedSoftkeysAreDisabledWithAReason) {
    PanelHarness panel;
    EXPECT_TRUE(panel.window().softkeys()->enabled(2));   // 对刀
    EXPECT_FALSE(panel.window().softkeys()->enabled(12)); // 序列加工
    panel.softkey(12);
    EXPECT_FALSE(panel.window().messageText().isEmpty());
    EXPECT_EQ(panel.window().currentPage()->id(), "monitor");
}

// 图形显示 opens the machine view, by the softkey and by the F1 key (both through the dispatcher);
// Esc comes back.
TEST(MonitorPage, TheGraphicDisplaySoftkeyOpensTheMachineView) {
    PanelHarness panel;
    EXPECT_TRUE(panel.window().softkeys()->label(1).contains(QStringLiteral("图形显示")));
    EXPECT_TRUE(panel.window().softkeys()->enabled(1));
    panel.softkey(1);
    EXPECT_EQ(panel.window().currentPage()->id(), "graphics");
    EXPECT_TRUE(panel.window().state().contains("graphics"));
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), "monitor");
    panel.key("F1");
    EXPECT_EQ(panel.window().currentPage()->id(), "graphics");
}

TEST(MonitorPage, ClearZeroesTheWorkCoordinateOfOneAxis) {
    PanelHarness panel;
    auto* monitor = panel.page<ui::MonitorPage>();
    EXPECT_NE(monitor->workText(0), "0.000");
    panel.softkey(5); // 清零
    panel.softkey(1); // X清零
    EXPECT_EQ(monitor->workText(0), "0.000");
    EXPECT_NE(monitor->workText(1), "0.000");
}

TEST(MdiPage, ALineTypedAndRunMovesTheMachineAndTheDroShowsIt) {
    PanelHarness panel;
    panel.key("MDI");
    auto* mdi = panel.page<ui::MdiPage>();
    ASSERT_NE(mdi, nullptr);
    panel.type("G90 G0 X10 Y5");
    EXPECT_TRUE(mdi->editing());
    panel.key("ENTER");
    EXPECT_FALSE(mdi->editing());
    EXPECT_EQ(mdi->lines().at(0), "G90 G0 X10 Y5");
    panel.softkey(1); // 执行(1)
    EXPECT_TRUE(mdi->resultText().contains(QStringLiteral("运行"))) << mdi->resultText().toStdString();
    panel.advance(5.0);
    EXPECT_TRUE(mdi->resultText().contains(QStringLiteral("完成"))) << mdi->resultText().toStdString();
    panel.key("MONITOR");
    auto* monitor = panel.page<ui::MonitorPage>();
    EXPECT_EQ(monitor->workText(0), "10.000");
    EXPECT_EQ(monitor->workText(1), "5.000");
}

TEST(MdiPage, TheSixLinesAreKeptInTheMachineFolder) {
    QString folder;
    {
        PanelHarness panel;
        panel.key("MDI");
        panel.key("DOWN");
        panel.key("DOWN");
        panel.type("M3 S1000");
        panel.key("ENTER");
        QFile block(QDir(panel.folder()).filePath("mdiblock"));
        ASSERT_TRUE(block.open(QIODevice::ReadOnly));
        QByteArray bytes = block.readAll();
        ASSERT_EQ(bytes.size(), 720);
        EXPECT_EQ(bytes.mid(240, 8), QByteArray("M3 S1000"));
        EXPECT_EQ(bytes.at(248), '\0');
    }
}

TEST(MdiPage, EscDropsAnEditAndASyntaxErrorShowsWithItsPosition) {
    PanelHarness panel;
    panel.key("MDI");
    auto* mdi = panel.page<ui::MdiPage>();
    panel.type("G1 X[1+");
    panel.key("ENTER");
    panel.softkey(1);
    EXPECT_TRUE(mdi->resultText().contains("mdi.nc:1:")) << "[" << mdi->resultText().toStdString() << "] " << panel.window().messageText().toStdString();
    QFile kept(QDir(panel.folder()).filePath("mdi.nc")); // the line ran from mdi.nc, as on the M350
    ASSERT_TRUE(kept.open(QIODevice::ReadOnly));
    EXPECT_EQ(kept.readAll(), QByteArray("G1 X[1+\n"));
    panel.key("ENTER");
    panel.type("G0 X1");
    panel.key("ESC");
    EXPECT_EQ(mdi->lines().at(0), "G1 X[1+");
}

// The spindle starts empty: releasing the drawbar with a tool in it would drop the tool (a crash).
TEST(IoPage, OutOpenLightsTheOutputLampAndOutCloseDarkensIt) {
    ui::MachineSession::Options empty;
    empty.tool = 0;
    PanelHarness panel(empty);
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    ASSERT_NE(io, nullptr);
    ASSERT_TRUE(io->selectFunction(750)); // 刀具松开/锁紧 on OUT01
    EXPECT_FALSE(io->outputLit(1));
    panel.softkey(1); // 输出开
    EXPECT_TRUE(io->outputLit(1));
    panel.advance(0.5); // the clamp cylinder answers on IN11
    EXPECT_TRUE(io->inputLit(11));
    panel.softkey(2); // 输出关
    EXPECT_FALSE(io->outputLit(1));
}

TEST(IoPage, ChangePolarityFlipsTheActiveLevelParameter) {
    PanelHarness panel;
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    ASSERT_TRUE(io->selectFunction(575)); // 固定对刀
    double before = panel.session().latest()->status.parameters.get(577);
    panel.softkey(4); // a factory parameter: a guest is asked the password the Param page asks (issue 26)
    EXPECT_EQ(panel.session().latest()->status.parameters.get(577), before);
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("权限不足")));
    ASSERT_TRUE(panel.window().prompt()->active());
    const params::UserLevel needed = controller::ParameterWrites::required(577);
    EXPECT_GE(needed, params::UserLevel::Admin);
    panel.type(ui::UserAccess::defaultPassword(needed));
    panel.key("ENTER");
    EXPECT_EQ(panel.session().userLevel(), needed);
    EXPECT_EQ(panel.session().latest()->status.parameters.get(577), 1.0 - before) << panel.window().messageText().toStdString();
}

TEST(IoPage, AStuckSensorDuringAToolChangeIsNamedByTheWatchdog) {
    PanelHarness panel;
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    ASSERT_TRUE(io->selectFunction(623)); // 刀具松开检测, IN11
    panel.softkey(7);                     // simulator: stuck at 0
    panel.key("MDI");
    panel.type("T2");
    panel.key("ENTER");
    panel.softkey(1);
    panel.key("IO");
    panel.advance(20.0);
    EXPECT_TRUE(io->watchText().contains("IN11")) << io->watchText().toStdString();
    EXPECT_TRUE(panel.window().alarmText().contains("IN11")) << panel.window().alarmText().toStdString();
    // said in the panel's language (the alarm's message id), the input by its Chinese function
    EXPECT_TRUE(panel.window().alarmText().contains(QStringLiteral("未变为1"))) << panel.window().alarmText().toStdString();
    EXPECT_FALSE(panel.window().alarmText().contains("never became")) << panel.window().alarmText().toStdString();
    EXPECT_EQ(panel.window().statusLine()->stateText(), QStringLiteral("故障"));
}

TEST(ProbePage, FixedToolSettingStoresTheTripHeightAndShowsIt) {
    PanelHarness panel;
    panel.key("PROBE");
    auto* probe = panel.page<ui::ProbePage>();
    ASSERT_NE(probe, nullptr);
    panel.softkey(3); // 固定对刀
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_EQ(panel.window().prompt()->question(), QStringLiteral("请输入固定对刀的刀具号:"));
    panel.key("BACKSPACE");
    panel.type("1");
    panel.key("ENTER");
    ASSERT_TRUE(panel.window().prompt()->active()); // Z轴工件原点是否已确定?
    panel.key("ESC");                               // no: only the tool's Z offset
    panel.advance(60.0);
    // T1 is 66.323 long; the setter's top is at -120: it trips with the nose at -53.677
    EXPECT_TRUE(probe->offsetText(1).contains("-53.677")) << probe->offsetText(1).toStdString();
    EXPECT_NEAR(panel.session().latest()->status.parameters.get(930), -53.677, 1e-3);
}

TEST(ProbePage, TeachStoresTheMachinePositionAsTheSetterPosition) {
    PanelHarness panel;
    panel.key("PROBE");
    auto* probe = panel.page<ui::ProbePage>();
    panel.softkey(6); // Z位置教导
    panel.key("ENTER");
    panel.advance(1.0); // O507 stores it
    double z = panel.session().latest()->status.machine(2);
    EXPECT_EQ(probe->fieldText("z"), QString::number(z, 'f', 3));
}

TEST(ProbePage, MultiToolSelectionGridTakesArrowsAndEnter) {
    PanelHarness panel;
    panel.key("PROBE");
    auto* probe = panel.page<ui::ProbePage>();
    panel.softkey(4);
    ASSERT_TRUE(probe->selecting());
    panel.key("ENTER");  // T1
    panel.key("RIGHT");
    panel.key("RIGHT");
    panel.key("ENTER");  // T3
    EXPECT_TRUE(probe->toolSelected(1));
    EXPECT_FALSE(probe->toolSelected(2));
    EXPECT_TRUE(probe->toolSelected(3));
    panel.key("ESC");
    EXPECT_FALSE(probe->selecting());
}

// 系统信息 counts the machine folder's programs each time it opens: every .nc (or .NC) file, in
// subfolders too; hidden folders and files, other files and a dangling link are not programs.
TEST(SystemPage, CountsTheMachineFoldersProgramsWhenItOpens) {
    PanelHarness panel;
    auto count = [&panel] {
        panel.page(QStringLiteral("system"));
        return panel.window().currentPage()->state().value("system_programs").toInt(-1);
    };
    const int before = count();
    ASSERT_GE(before, 0);
    const QDir folder(panel.folder());
    ASSERT_TRUE(folder.mkpath(QStringLiteral("mine/deeper")));
    ASSERT_TRUE(folder.mkpath(QStringLiteral(".hidden")));
    putFile(folder.filePath(QStringLiteral("mine/a.nc")), "G0 X0\n");
    putFile(folder.filePath(QStringLiteral("mine/deeper/B.NC")), "G0 X0\n");
    putFile(folder.filePath(QStringLiteral("mine/notes.txt")), "not a program\n");
    putFile(folder.filePath(QStringLiteral(".hidden/c.nc")), "G0 X0\n");
    putFile(folder.filePath(QStringLiteral(".d.nc")), "G0 X0\n");
    ASSERT_TRUE(QFile::link(folder.filePath(QStringLiteral("gone.nc")), folder.filePath(QStringLiteral("mine/dangling.nc"))));
    panel.page(QStringLiteral("monitor"));
    EXPECT_EQ(count(), before + 2);
}

TEST(Panel, SwitchingLanguageChangesTheWords) {
    PanelHarness panel;
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("连续"));
    panel.act([] {
        OperatorAction a;
        a.kind = OperatorAction::Kind::Language;
        a.name = "en";
        return a;
    }());
    EXPECT_EQ(panel.window().statusLine()->modeText(), "CONT");
    EXPECT_TRUE(panel.window().softkeys()->label(4).contains("Go Home"));
    panel.act([] {
        OperatorAction a;
        a.kind = OperatorAction::Kind::Language;
        a.name = "zh_CN";
        return a;
    }());
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("连续"));
}

TEST(Panel, ContStepMpgKeyCyclesTheMode) {
    PanelHarness panel;
    panel.key("CONT_STEP_MPG");
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("寸动"));
    panel.key("CONT_STEP_MPG");
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("手轮"));
    panel.key("CONT_STEP_MPG");
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("连续"));
}

TEST(Panel, StepJogMovesOneStep) {
    PanelHarness panel;
    auto* monitor = panel.page<ui::MonitorPage>();
    double x = panel.session().latest()->status.machine(0);
    panel.key("CONT_STEP_MPG");
    panel.key("STEP_1");
    panel.key("JOG_X+");
    panel.advance(1.0);
    EXPECT_EQ(monitor->machineText(0), QString::number(x + 1.0, 'f', 3));
}

TEST(Panel, MacroDialogWaitsForTheOperatorsAnswer) {
    PanelHarness panel;
    panel.key("MDI");
    panel.type("#1505=1(continue?)");
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(0.2);
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_EQ(panel.window().prompt()->question(), "continue?");
    panel.advance(2.0);
    EXPECT_TRUE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.session().latest()->status.dialog.has_value());
    EXPECT_EQ(panel.session().latest()->status.run, controller::PanelStatus::Run::Running) << "the run waits";
    panel.key("ENTER");
    panel.advance(0.2);
    EXPECT_FALSE(panel.window().prompt()->active());
    EXPECT_EQ(panel.session().latest()->status.run, controller::PanelStatus::Run::Finished);
}

} // namespace m350::test

namespace m350::test {

TEST(Panel, AtPowerOnThePanelAsksToHomeAndEnterHomesEveryAxis) {
    ui::MachineSession::Options powerOn;
    powerOn.homed = false;
    PanelHarness panel(powerOn);
    panel.advance(0.1);
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_EQ(panel.window().prompt()->question(), QStringLiteral("是否进行开机寻零操作?"));
    EXPECT_FALSE(panel.session().latest()->status.homed[0]);
    panel.key("ENTER");
    // the default machine's fndzero.nc homes Z, X and Y one after another in virtual time
    panel.advance(0.1);
    EXPECT_EQ(panel.session().latest()->activity, ui::Activity::Homing);
    panel.advance(30.0);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_TRUE(panel.session().latest()->status.homed[static_cast<std::size_t>(axis)]) << axis;
    }
}

TEST(Panel, RecordedActionsReadBackAsAReplay) {
    PanelHarness panel;
    QTemporaryDir dir;
    QString path = dir.filePath("session.jsonl");
    QString error;
    ASSERT_TRUE(panel.window().startRecording(path, &error)) << error.toStdString();
    panel.key("MDI");
    panel.type("G0 X1");
    panel.key("ENTER");
    panel.advance(0.5);
    panel.softkey(1);
    auto actions = ui::readReplay(path, &error);
    ASSERT_TRUE(actions) << error.toStdString();
    ASSERT_EQ(actions->size(), 4u);
    EXPECT_EQ((*actions)[0].name, "MDI");
    EXPECT_EQ((*actions)[1].text, "G0 X1");
    EXPECT_EQ((*actions)[3].softkey, 1);
    EXPECT_NEAR((*actions)[3].t, 0.5, 0.02) << "stamped with the machine's virtual time";
}

} // namespace m350::test
