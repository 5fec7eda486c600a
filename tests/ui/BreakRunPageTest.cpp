// 断点加工 through the operator's path: the Monitor's F6 opens the page, 指定行加工 asks the line and
// confirms, the run starts there; PAUSE, RESET and 暂停断点加工 carry on at the paused line.
#include "PanelHarness.h"

#include "ui/pages/BreakRunPage.h"

#include <QDir>
#include <cmath>
#include <QFile>
#include <QJsonObject>

namespace m350::test {

namespace {

using Run = controller::PanelStatus::Run;

// Work X60 at line 5 is 5 s of feed at 600 mm/min from X10.
const char* kProgram = "G90 G54\n"        // 1
                       "G0 X10 Y10\n"     // 2
                       "M3 S8000\n"       // 3
                       "G91 G1 X20 F600\n" // 4
                       "X30\n"            // 5
                       "G90 Y40\n"        // 6
                       "M5\n"             // 7
                       "M30\n";           // 8

QString writeProgram(const QString& folder) {
    QString path = QDir(folder).filePath("brk.nc");
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(kProgram);
    return path;
}

const ui::PanelSnapshot& latest(PanelHarness& panel) { return *panel.session().latest(); }

void load(PanelHarness& panel) {
    QString error;
    auto action = ui::OperatorAction::fromJson(QJsonObject{{"t", 0}, {"load", writeProgram(panel.folder())}}, &error);
    ASSERT_TRUE(action) << error.toStdString();
    panel.act(*action);
}

} // namespace

TEST(BreakRunPage, StartLineRunsFromTheLineWithTheStateBuiltBeforeIt) {
    PanelHarness panel;
    load(panel);
    panel.key("MONITOR");
    panel.softkey(6);
    ASSERT_NE(panel.page<ui::BreakRunPage>(), nullptr);
    panel.softkey(1); // 指定行加工: 起始加工行号:
    panel.type("5");
    panel.key("ENTER");
    panel.key("ENTER"); // 文件扫描并定位成功,是否进行启动加工?
    panel.advance(0.2);
    EXPECT_EQ(latest(panel).status.run, Run::Running) << latest(panel).lastError.toStdString();
    EXPECT_NE(latest(panel).status.modalLine.find("G91"), std::string::npos); // line 4 set G91
    // line 4's feed from X10 to X30 along Y10 never happens: the machine comes over to X30 directly
    for (int frame = 0; frame < 60 * 30 && latest(panel).status.run == Run::Running; ++frame) {
        panel.advance(1.0 / 60.0);
        const auto& work = latest(panel).status.work;
        EXPECT_FALSE(std::abs(work(1) - 10.0) < 1e-6 && work(0) > 11.0 && work(0) < 29.0) << "X" << work(0);
    }
    const auto& s = latest(panel);
    EXPECT_EQ(s.status.run, Run::Finished) << s.lastError.toStdString();
    EXPECT_NEAR(s.status.work(0), 60.0, 1e-6); // X30 more from X30, then Y40
    EXPECT_NEAR(s.status.work(1), 40.0, 1e-6);
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), "monitor");
}

TEST(BreakRunPage, PauseResetAndPauseResumeContinueAtThePausedLine) {
    PanelHarness panel;
    load(panel);
    panel.key("START");
    panel.advance(6.0); // inside line 5's move
    panel.key("PAUSE");
    panel.advance(0.5);
    panel.key("RESET");
    EXPECT_EQ(latest(panel).breakPoints.pauseLine, 5);
    EXPECT_EQ(latest(panel).breakPoints.keptLine, 5); // kept in the machine folder for 断电断点加工
    panel.key("MONITOR");
    panel.softkey(6);
    panel.softkey(3); // 暂停断点加工
    panel.key("ENTER");
    panel.advance(30.0);
    const auto& s = latest(panel);
    EXPECT_EQ(s.status.run, Run::Finished) << s.lastError.toStdString();
    EXPECT_NEAR(s.status.work(0), 60.0, 1e-6); // where the uninterrupted run ends
    EXPECT_NEAR(s.status.work(1), 40.0, 1e-6);
    QFile kept(QDir(panel.folder()).filePath("breakpoint"));
    EXPECT_TRUE(kept.exists());
}

TEST(BreakRunPage, ARefusalGoesToTheMessageLine) {
    PanelHarness panel;
    load(panel);
    panel.key("MONITOR");
    panel.softkey(6);
    panel.softkey(1);
    panel.type("99");
    panel.key("ENTER");
    panel.key("ENTER");
    // by message id, in the panel's language (zh_CN)
    EXPECT_NE(latest(panel).lastError.indexOf(QStringLiteral("第99行不在brk.nc中")), -1) << latest(panel).lastError.toStdString();
    EXPECT_EQ(latest(panel).status.run, Run::Idle);
}

} // namespace m350::test
