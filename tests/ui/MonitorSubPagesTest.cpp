// The Monitor's sub-pages (坐标管理, 分中, 加工统计) and the 系统日志, through the operator's path.
#include "tests/ui/PanelHarness.h"

#include "core/config/MachineConfig.h"

#include "ui/pages/CoordPage.h"
#include "ui/pages/LogPage.h"
#include "ui/pages/MiddlePage.h"
#include "ui/pages/MonitorPage.h"
#include "ui/pages/RecordPage.h"
#include "ui/panel/PromptBox.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <filesystem>
#include <string>

namespace m350::test {

namespace {

double work(PanelHarness& panel, int axis) { return panel.session().latest()->status.work(axis); }
double machine(PanelHarness& panel, int axis) { return panel.session().latest()->status.machine(axis); }

void mdi(PanelHarness& panel, const QString& line, double seconds) {
    panel.key("MDI");
    panel.type(line);
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(seconds);
}

} // namespace

TEST(CoordPage, SetXGivesTheCurrentPointTheTypedWorkCoordinate) {
    PanelHarness panel;
    panel.key("MONITOR");
    panel.softkey(8); // 坐标管理
    ASSERT_EQ(panel.window().currentPage()->id(), "coord");
    panel.softkey(2); // 设置X
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("BACKSPACE");
    panel.type("25.5");
    panel.key("ENTER");
    EXPECT_NEAR(work(panel, 0), 25.5, 1e-9);
    auto* coord = panel.page<ui::CoordPage>();
    EXPECT_EQ(coord->offsetText(1, 0), QString::number(machine(panel, 0) - 25.5, 'f', 3));
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), "monitor");
}

TEST(CoordPage, DeeperAndMoveUpShiftOnlyTheCommonOffsetsZByTheStep) {
    PanelHarness panel;
    panel.page("coord");
    const double z = work(panel, 2);
    const double g54z = panel.session().latest()->status.workOffsets[1](2);
    panel.softkey(5); // Z轴调整值
    panel.key("BACKSPACE");
    panel.key("BACKSPACE");
    panel.key("BACKSPACE");
    panel.type("0.2");
    panel.key("ENTER");
    EXPECT_DOUBLE_EQ(panel.page<ui::CoordPage>()->zStep(), 0.2);
    panel.softkey(6); // 加深: the work zero goes down, the tool is higher above it
    EXPECT_NEAR(work(panel, 2), z + 0.2, 1e-9);
    EXPECT_NEAR(panel.session().latest()->status.workOffsets[8](2), -0.2, 1e-9);
    EXPECT_DOUBLE_EQ(panel.session().latest()->status.workOffsets[1](2), g54z) << "G54 is not touched";
    panel.softkey(7); // 抬高
    panel.softkey(7);
    EXPECT_NEAR(work(panel, 2), z - 0.2, 1e-9);
}

TEST(CoordPage, SelectCoordMakesG55Active) {
    PanelHarness panel;
    panel.page("coord");
    panel.softkey(1);
    panel.type("2");
    panel.key("ENTER");
    EXPECT_EQ(panel.session().latest()->status.workSystem, 2);
    panel.softkey(1);
    panel.type("9");
    panel.key("ENTER");
    EXPECT_EQ(panel.session().latest()->status.workSystem, 2) << "9 is no work system";
    EXPECT_FALSE(panel.window().messageText().isEmpty());
}

TEST(MiddlePage, CentresBetweenTwoRecordedXPositions) {
    PanelHarness panel;
    mdi(panel, "G53 G0 X100", 3.0);
    panel.key("MONITOR");
    panel.softkey(10); // 分中
    ASSERT_EQ(panel.window().currentPage()->id(), "middle");
    panel.softkey(1); // 记录X at machine X 100
    panel.page("mdi");
    panel.type("G53 G0 X160");
    panel.key("ENTER");
    panel.softkey(1);
    panel.advance(3.0);
    panel.page("middle");
    panel.softkey(2); // 分中X at machine X 160
    auto* middle = panel.page<ui::MiddlePage>();
    ASSERT_TRUE(middle->middle(0).has_value());
    EXPECT_NEAR(*middle->middle(0), 130.0, 1e-9);
    EXPECT_NEAR(work(panel, 0), 30.0, 1e-9) << "the midpoint is the work X zero";
}

TEST(MiddlePage, ThreePointsOnACircleCentreItsWorkZero) {
    auto centre = ui::MiddlePage::circleCentre({10, 0}, {0, 10}, {-10, 0});
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x(), 0.0, 1e-12);
    EXPECT_NEAR(centre->y(), 0.0, 1e-12);
    EXPECT_FALSE(ui::MiddlePage::circleCentre({0, 0}, {1, 1}, {2, 2}));
    auto offset = ui::MiddlePage::circleCentre({105, 50}, {100, 55}, {95, 50});
    ASSERT_TRUE(offset);
    EXPECT_NEAR(offset->x(), 100.0, 1e-9);
    EXPECT_NEAR(offset->y(), 50.0, 1e-9);
}

TEST(RecordPage, AFinishedProgramCountsAndClearAsksFirst) {
    PanelHarness panel;
    panel.loadProgram("piece.nc", "G91 G1 X10 F600\nM30\n");
    panel.key("START");
    panel.advance(3.0);
    panel.page("record");
    auto* record = panel.page<ui::RecordPage>();
    EXPECT_TRUE(record->recordText().contains("piece.nc")) << record->recordText().toStdString();
    EXPECT_EQ(panel.session().latest()->workRecord.finished, 1);
    EXPECT_GT(panel.session().latest()->workRecord.lastPiece, 0.9);
    EXPECT_EQ(panel.session().latest()->status.pieceCount, 1) << "M30 counts the piece";
    panel.softkey(1);
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ESC");
    EXPECT_EQ(panel.session().latest()->status.pieceCount, 1) << "Esc keeps the record";
    panel.softkey(1);
    panel.key("ENTER");
    EXPECT_EQ(panel.session().latest()->status.pieceCount, 0);
    EXPECT_EQ(panel.session().latest()->workRecord.finished, 0);
}

TEST(LogPage, OperationsAndAlarmsAreLoggedNewestFirstAndKept) {
    QString folder;
    {
        PanelHarness panel;
        folder = panel.folder();
        mdi(panel, "G0 X1", 1.0);
        panel.key("ESTOP");
        panel.key("RESET");
        panel.key("LOG");
        auto* log = panel.page<ui::LogPage>();
        ASSERT_GE(log->rows(), 3);
        EXPECT_TRUE(log->eventText(0).contains(QStringLiteral("复位"))) << log->eventText(0).toStdString();
        EXPECT_TRUE(log->eventText(1).contains(QStringLiteral("故障"))) << log->eventText(1).toStdString();
        EXPECT_TRUE(log->eventText(3).contains(QStringLiteral("MDI运行: G0 X1"))) << log->eventText(3).toStdString();
        QFile file(QDir(folder).filePath("system-log.tsv"));
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        EXPECT_TRUE(file.readAll().contains("mdi\tG0 X1"));
    }
}

} // namespace m350::test

namespace m350::test {

// On a FANUC with the additional work systems the Monitor names the one in force, and the modal
// line says G68 while the program is turned.
TEST(MonitorPage, ItNamesAnAdditionalWorkSystem) {
    QTemporaryDir dir;
    const std::filesystem::path folder = std::filesystem::path(dir.path().toStdString()) / "fanuc-30i";
    std::filesystem::copy(config::bundledMachinesDirectory() + "/fanuc-30i", folder,
                          std::filesystem::copy_options::recursive);
    PanelHarness panel(QString::fromStdString(folder.string()));
    panel.loadProgram("g54-1.nc", "G10 L20 P123 X5.\nG54.1 P123\nG68 X0 Y0 R15.\nM00\nG69\nM30\n");
    panel.key("START");
    panel.advance(0.5);
    panel.key("MONITOR");
    auto* monitor = panel.page<ui::MonitorPage>();
    EXPECT_EQ(monitor->infoText("coord"), QStringLiteral("G54.1 P123"));
    const std::string modal = panel.session().latest()->status.modalLine;
    EXPECT_NE(modal.find(" G54.1 P123 G68 "), std::string::npos) << modal;
}

} // namespace m350::test
