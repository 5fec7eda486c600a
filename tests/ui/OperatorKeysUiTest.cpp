// Keys an M350 owner wires or adds: the external keys, extern START / PAUSE / E-stop on inputs
// (pressed from the IO page's simulator row, as a trainer does; IN17-IN20 are free on the default
// machine) and the FUNC K01-K14 keys of the
// 定制功能 page. A hook marks that it ran by switching an output the default machine leaves unwired.
#include "PanelHarness.h"

#include "ui/pages/CustomKeysPage.h"
#include "ui/pages/IoPage.h"

namespace m350::test {

namespace {

using Run = controller::PanelStatus::Run;

void writeHook(const QString& folder, const QString& name, const QByteArray& text) {
    QFile file(QDir(folder).filePath(name));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
}

int output(PanelHarness& panel, int port) {
    return panel.session().latest()->status.outputs[static_cast<std::size_t>(port - 1)];
}

Run run(PanelHarness& panel) { return panel.session().latest()->status.run; }

void wire(PanelHarness& panel, int parameter, int pin) {
    panel.session().setParameter(parameter, pin);
    panel.session().setParameter(parameter + 1, 1);
    panel.session().setParameter(parameter + 2, 1);
}

// the IO page's 模拟:按下 on the port of `parameter`
void pressOnIoPage(PanelHarness& panel, int parameter) {
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    ASSERT_NE(io, nullptr);
    panel.advance(0.05); // the table shows the new wiring
    ASSERT_TRUE(io->selectFunction(parameter)) << parameter;
    panel.softkey(12);
}

bool logged(PanelHarness& panel, const std::string& detail) {
    for (const files::LogEntry& entry : *panel.session().latest()->log) {
        if (entry.detail.find(detail) != std::string::npos) {
            return true;
        }
    }
    return false;
}

} // namespace

TEST(OperatorKeys, AnExternalKeyOnItsInputRunsItsHook) {
    PanelHarness panel;
    writeHook(panel.folder(), "extnc0-1.nc", "#1560=1\n");
    wire(panel, 581, 17); // external key 1 on IN17; param 272 = 0: it runs extnc0-1.nc
    pressOnIoPage(panel, 581);
    panel.advance(1.0);
    EXPECT_EQ(output(panel, 9), 1);
    EXPECT_TRUE(logged(panel, ": extnc0-1.nc"));
}

TEST(OperatorKeys, ExternPauseHoldsAndExternStartGoesOn) {
    PanelHarness panel;
    writeHook(panel.folder(), "extnc1-1.nc", "G91 G1 X100 F600\n#1561=1\n");
    wire(panel, 584, 17); // external key 2
    wire(panel, 599, 18); // extern START
    wire(panel, 602, 19); // extern PAUSE
    pressOnIoPage(panel, 584);
    panel.advance(1.0);
    ASSERT_EQ(run(panel), Run::Running);
    pressOnIoPage(panel, 602);
    panel.advance(0.5);
    EXPECT_EQ(run(panel), Run::Hold);
    const double x = panel.session().latest()->status.machine(0);
    panel.advance(2.0);
    EXPECT_NEAR(panel.session().latest()->status.machine(0), x, 1e-9);
    pressOnIoPage(panel, 599);
    panel.advance(0.5);
    EXPECT_EQ(run(panel), Run::Running);
    panel.advance(15.0);
    EXPECT_EQ(output(panel, 10), 1);
}

TEST(OperatorKeys, TheExternEStopHoldsTheMachineUntilItIsReleased) {
    PanelHarness panel;
    wire(panel, 605, 20);
    panel.key("IO");
    auto* io = panel.page<ui::IoPage>();
    panel.advance(0.05);
    ASSERT_TRUE(io->selectFunction(605));
    panel.softkey(8); // simulator: stuck at 1, the mushroom button latched
    panel.advance(0.1);
    EXPECT_EQ(run(panel), Run::EStop);
    EXPECT_TRUE(panel.window().alarmText().contains("IN20")) << panel.window().alarmText().toStdString();
    panel.key("RESET");
    panel.advance(0.1);
    EXPECT_EQ(run(panel), Run::EStop);
    panel.softkey(11); // released
    panel.key("RESET");
    panel.advance(0.1);
    EXPECT_EQ(run(panel), Run::Idle);
}

TEST(OperatorKeys, AFuncKeyRunsExtButtonWithItsMCode) {
    PanelHarness panel;
    writeHook(panel.folder(), "ext_button.nc", "#[1560+#1996-252]=1\n"); // K03 = M252: OUT09
    panel.softkey(7); // the Monitor page's 定制功能
    auto* page = panel.page<ui::CustomKeysPage>();
    ASSERT_NE(page, nullptr);
    EXPECT_TRUE(page->state().value("runs").toString().contains("ext_button.nc"));
    panel.key("RIGHT");
    panel.key("RIGHT");
    panel.key("ENTER");
    panel.advance(1.0);
    EXPECT_EQ(output(panel, 9), 1);
    EXPECT_EQ(output(panel, 10), 0);
    EXPECT_TRUE(logged(panel, "FUNC K03: ext_button.nc"));
    panel.key("DOWN"); // K10 = M259: OUT16 is no output of this test, the hook still runs
    EXPECT_EQ(page->state().value("selected_key").toInt(), 10);
    panel.key("ESC");
    EXPECT_EQ(panel.page<ui::CustomKeysPage>(), nullptr);
}

} // namespace m350::test
