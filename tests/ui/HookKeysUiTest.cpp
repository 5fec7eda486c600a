// The panel's keys, softkeys and events that run the machine folder's hook files: each test
// writes its own hook into the panel's copy of the default machine and presses the key an
// operator would. A hook marks that it ran by switching an output the default machine leaves
// unwired (OUT09-OUT12), which the snapshot shows.
#include "PanelHarness.h"

#include "ui/pages/ProbePage.h"
#include "ui/panel/PromptBox.h"

namespace m350::test {

namespace {

void writeHook(const QString& folder, const QString& name, const QByteArray& text) {
    QFile file(QDir(folder).filePath(name));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
}

int output(PanelHarness& panel, int port) {
    return panel.session().latest()->status.outputs[static_cast<std::size_t>(port - 1)];
}

ui::MachineSession::Options unhomed() {
    ui::MachineSession::Options options;
    options.homed = false;
    return options;
}

} // namespace

TEST(HookKeys, GoHomeAllRunsTheFoldersFndzeroAndOneAxisItsFndFile) {
    PanelHarness panel(unhomed());
    panel.advance(0.1);
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ESC"); // the boot homing prompt: not now
    writeHook(panel.folder(), "fndzero.nc", "#1560=1\nM98P501X2\nM98P501X0\nM98P501X1\n");
    writeHook(panel.folder(), "fndZ.nc", "#1561=1\nM98P501X2\n");
    panel.key("F4"); // 回机械原点
    panel.key("F3"); // Z only
    panel.advance(10.0);
    EXPECT_EQ(output(panel, 10), 1);
    EXPECT_TRUE(panel.session().latest()->status.homed[2]);
    EXPECT_FALSE(panel.session().latest()->status.homed[0]);
    panel.key("F6"); // every axis
    panel.advance(0.1);
    EXPECT_EQ(panel.session().latest()->activity, ui::Activity::Homing);
    panel.advance(30.0);
    EXPECT_EQ(output(panel, 9), 1);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_TRUE(panel.session().latest()->status.homed[static_cast<std::size_t>(axis)]) << axis;
    }
    EXPECT_EQ(panel.session().latest()->activity, ui::Activity::None);
}

TEST(HookKeys, GoHomeWithAbsoluteServosRunsAbszeroAndAbsZ) {
    PanelHarness panel(unhomed());
    panel.advance(0.1);
    panel.key("ESC"); // the boot homing prompt: not now
    panel.session().setParameter(100, 1); // 机械零点方式: absolute servos
    writeHook(panel.folder(), "fndzero.nc", "#1560=1\nM98P501X2\n");
    writeHook(panel.folder(), "abszero.nc", "#1562=1\nM98P501X2\nM98P501X0\nM98P501X1\n");
    writeHook(panel.folder(), "absZ.nc", "#1563=1\nM98P501X2\n");
    panel.key("F4"); // 回机械原点
    panel.key("F3"); // Z only
    panel.advance(10.0);
    EXPECT_EQ(output(panel, 12), 1);
    panel.key("F6");
    panel.advance(30.0);
    EXPECT_EQ(output(panel, 11), 1);
    EXPECT_EQ(output(panel, 9), 0) << "fndzero.nc is for home switches";
    EXPECT_TRUE(panel.session().latest()->status.homed[0]);
}

TEST(HookKeys, GoWorkZeroAllRunsGotozero) {
    PanelHarness panel;
    writeHook(panel.folder(), "gotozero.nc", "#1560=1\nG90 G53 G00 Z0\n");
    panel.key("F3"); // 回工件原点
    panel.key("F6");
    panel.advance(5.0);
    EXPECT_EQ(output(panel, 9), 1);
}

TEST(HookKeys, UserKeysRunTheirHookOrSwitchTheirOutput) {
    PanelHarness panel;
    // 0: the key runs key-N.nc (the factory value, 1, switches OUT1)
    panel.session().setParameter(210, 0);
    panel.session().setParameter(213, 0);
    writeHook(panel.folder(), "key-1.nc", "#1560=1\n");
    panel.key("K1");
    panel.advance(1.0);
    EXPECT_EQ(output(panel, 9), 1);

    panel.session().setParameter(211, 10); // K2 switches OUT10
    panel.key("K2");
    EXPECT_EQ(output(panel, 10), 1);
    panel.key("K2");
    EXPECT_EQ(output(panel, 10), 0);

    panel.key("K4"); // no key-4.nc in the folder
    EXPECT_TRUE(panel.session().latest()->lastError.contains("key-4.nc")) << panel.session().latest()->lastError.toStdString();
}

TEST(HookKeys, MCodeKeysRunTheirHooks) {
    PanelHarness panel;
    writeHook(panel.folder(), "M8.nc", "#1560=1\n");
    panel.key("M8");
    panel.advance(1.0);
    EXPECT_EQ(output(panel, 9), 1);
    // the default machine's own M3.nc: M3 at param 85's speed
    panel.key("M3");
    panel.advance(5.0);
    EXPECT_EQ(panel.session().latest()->status.spindle, machine::SpindleState::Forward);
    EXPECT_NEAR(panel.session().latest()->status.spindleRpm, 18000.0, 1e-6);
}

TEST(HookKeys, FixedSettingOfAnotherToolRunsTncThenProbeNc) {
    PanelHarness panel;
    writeHook(panel.folder(), "T.nc", "#1560=#1504\nT#1504\n");
    writeHook(panel.folder(), "probe.nc", "#[1560+#1502]=1\nM98 P502\n"); // mode 2: OUT11
    panel.key("PROBE");
    panel.softkey(3); // 固定对刀
    panel.key("BACKSPACE");
    panel.type("2");
    panel.key("ENTER");
    panel.key("ESC"); // Z work zero not set: mode 2, the tool's Z offset only
    panel.advance(90.0);
    EXPECT_EQ(panel.session().latest()->status.tool, 2);
    EXPECT_EQ(output(panel, 9), 1);  // T.nc ran with #1504 = 2
    EXPECT_EQ(output(panel, 11), 1); // then probe.nc with #1502 = 2
    EXPECT_NEAR(panel.session().latest()->status.parameters.get(931), -120.0 + 71.88, 1e-3);
}

TEST(HookKeys, MultiToolSettingRunsMulprobeWithTheChosenTools) {
    PanelHarness panel;
    writeHook(panel.folder(), "mulprobe.nc", "#1560=[#1970==1]\n#1561=[#1971==3]\n#1562=[#1972!=0]\n");
    panel.key("PROBE");
    panel.softkey(4);  // the selection grid
    panel.key("ENTER"); // T1
    panel.key("RIGHT");
    panel.key("RIGHT");
    panel.key("ENTER"); // T3
    panel.softkey(4);   // 一键对刀?
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ENTER");
    panel.advance(1.0);
    EXPECT_EQ(output(panel, 9), 1);
    EXPECT_EQ(output(panel, 10), 1);
    EXPECT_EQ(output(panel, 11), 0); // the rest of the list is 0
}

TEST(HookKeys, PauseRunsPauseNcAndStartGoesBackFirst) {
    PanelHarness panel;
    writeHook(panel.folder(), "pause.nc", "#1560=1\nG91 G00 Z5\nG90\n");
    panel.loadProgram("long.nc", "G91 G01 X200 F600\nG90\nM30\n");
    panel.key("START");
    panel.advance(2.0);
    double z = panel.session().latest()->status.machine(2);
    panel.key("PAUSE");
    panel.advance(2.0);
    EXPECT_EQ(output(panel, 9), 1);
    EXPECT_NEAR(panel.session().latest()->status.machine(2), z + 5.0, 1e-6);
    panel.key("START");
    panel.advance(30.0);
    EXPECT_EQ(panel.session().latest()->status.run, controller::PanelStatus::Run::Finished);
    EXPECT_NEAR(panel.session().latest()->status.machine(2), z, 1e-6);
}

TEST(HookKeys, PowerOnRunsSysstartBeforeTheBootHomingPrompt) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    writeHook(*folder, "sysstart.nc", "#1560=1\nM98P501X2\nM98P501X0\nM98P501X1\n");
    PanelHarness panel(*folder, unhomed());
    panel.advance(0.1);
    EXPECT_EQ(panel.session().latest()->activity, ui::Activity::Hook);
    EXPECT_FALSE(panel.window().prompt()->active()); // asked only once sysstart.nc has ended
    panel.advance(30.0);
    EXPECT_EQ(output(panel, 9), 1);
    EXPECT_TRUE(panel.session().latest()->status.homed[0]);
    EXPECT_FALSE(panel.window().prompt()->active()); // homed by sysstart.nc: nothing to ask
}

} // namespace m350::test
