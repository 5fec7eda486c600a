// MGETDATA to a slave that does not answer, on the panel: the run waits the controller's 16 s,
// then the alarm line names the slave in the panel's language (the alarm's message id), and the
// English words are the core's own message.
#include "PanelHarness.h"

#include <QTemporaryDir>

namespace m350::test {

namespace {

// A copy of the default machine with Modbus RTU on (parameter 279) and no modbus.toml: no slave.
QString machineWithModbusOn(const QTemporaryDir& dir) {
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    EXPECT_TRUE(folder) << error.toStdString();
    const QString params = QDir(*folder).filePath("params.toml");
    QString text = fileText(params);
    EXPECT_TRUE(text.contains("[params]\n"));
    text.replace("[params]\n", "[params]\n279 = 1\n");
    putFile(params, text.toUtf8());
    return *folder;
}

void language(PanelHarness& panel, const char* name) {
    ui::OperatorAction a;
    a.kind = ui::OperatorAction::Kind::Language;
    a.name = name;
    panel.act(a);
}

} // namespace

TEST(ModbusOnThePanel, ASilentSlaveAlarmsAfterTheTimeoutInThePanelsLanguage) {
    QTemporaryDir dir;
    PanelHarness panel(machineWithModbusOn(dir));
    panel.loadProgram("vfd.nc", "#200 = 1\nMGETDATA[200,5,0,2,3,300]\nM30\n");
    panel.key("START");
    panel.advance(15.0);
    EXPECT_TRUE(panel.window().alarmText().isEmpty()) << panel.window().alarmText().toStdString();
    panel.advance(2.0);
    EXPECT_EQ(panel.window().alarmText(),
              QStringLiteral("vfd.nc:2:1: MGETDATA：Modbus从站5在16秒内无应答；在控制器上这会使MGETDATA卡住，直到重启"
                             "（modbus.toml中没有[slave.5]）"));
    language(panel, "en");
    const auto alarm = panel.session().latest()->status.alarm;
    ASSERT_TRUE(alarm);
    EXPECT_EQ(panel.window().alarmText().toStdString(), "vfd.nc:2:1: " + alarm->message);
    EXPECT_NE(alarm->message.find("Modbus slave 5 did not answer within 16 s"), std::string::npos) << alarm->message;
    language(panel, "zh_CN");
}

} // namespace m350::test
