// 刀具表 as an operator uses it, through the panel's keys: the Probe page opens it, a field edited
// in the prompt is the tool's parameter and lands in tool.tbl, touch off, delete, a LinuxCNC file
// imported and the table exported, and the table still there after a restart.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/ToolTablePage.h"
#include "ui/panel/PromptBox.h"

#include "ui/session/UserAccess.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <sys/stat.h>

#include <future>

namespace m350::test {

namespace {

using Column = ui::ToolTablePage::Column;

double parameter(PanelHarness& panel, int number) { return panel.session().latest()->status.parameters.get(number); }

// Clears the prompt's text and types `text`, then Enter.
void answer(PanelHarness& panel, const QString& text) {
    while (!panel.window().prompt()->textValue().isEmpty()) {
        panel.key("BACKSPACE");
    }
    panel.type(text);
    panel.key("ENTER");
}

ui::ToolTablePage* openTable(PanelHarness& panel) {
    panel.key("PROBE");
    panel.softkey(2);
    return panel.page<ui::ToolTablePage>();
}

} // namespace

TEST(ToolTablePage, TheProbePageOpensItAndItListsTheMagazineAndTheVirtualTools) {
    PanelHarness panel;
    ui::ToolTablePage* page = openTable(panel);
    ASSERT_NE(page, nullptr) << "F2 of the Probe page";
    EXPECT_EQ(page->rowCount(), 18) << "T1-T16 and the virtual T17, T18 that have offsets";
    EXPECT_EQ(page->cellText(0, Column::Z), QStringLiteral("-53.677"));
    EXPECT_EQ(page->cellText(16, Column::Tool), QStringLiteral("17"));
    panel.key("ESC");
    EXPECT_EQ(panel.window().currentPage()->id(), QStringLiteral("probe"));
}

TEST(ToolTablePage, AFieldEditedInThePromptIsTheToolsParameterAndIsSavedInToolTbl) {
    PanelHarness panel;
    ui::ToolTablePage* page = openTable(panel);
    ASSERT_NE(page, nullptr);
    panel.key("DOWN");
    ASSERT_EQ(page->selectedTool(), 2);
    ASSERT_EQ(page->selectedColumn(), Column::Z);
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("权限不足"))) << "a guest changes no Z (issue 26)";
    answer(panel, ui::UserAccess::defaultPassword(params::UserLevel::Operator));
    EXPECT_EQ(panel.window().prompt()->textValue(), QStringLiteral("-48.120")) << "the value to change";
    answer(panel, "-50.5");
    EXPECT_EQ(parameter(panel, 931), -50.5) << "T2's Z is param 931";
    for (int i = 0; i < 4; ++i) {
        panel.key("RIGHT"); // diameter, rpm, teeth, type
    }
    ASSERT_EQ(page->selectedColumn(), Column::Type);
    panel.key("ENTER");
    answer(panel, "2");
    EXPECT_EQ(page->cellText(1, Column::Type), ui::ToolTablePage::typeName(tools::ToolType::Ball));
    panel.key("LEFT");
    panel.key("ENTER");
    answer(panel, "0");
    // the tool table's refusal by message id, in the panel's language
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("刀具2：刀具至少有1个齿")))
        << panel.window().messageText().toStdString();
    const QString saved = fileText(QDir(panel.folder()).filePath("tool.tbl"));
    EXPECT_TRUE(saved.contains(QStringLiteral("\nT2 P2 Z-50.5 ;{type=ball}\n"))) << saved.toStdString();
    EXPECT_TRUE(fileText(QDir(panel.folder()).filePath("params.toml")).contains(QStringLiteral("931 = -50.5")));
}

TEST(ToolTablePage, TouchOffMakesTheDisplayReadTheMeasuredZ) {
    ui::MachineSession::Options options;
    options.tool = 3;
    PanelHarness panel(options);
    ui::ToolTablePage* page = openTable(panel);
    ASSERT_NE(page, nullptr);
    panel.softkey(4);
    answer(panel, ui::UserAccess::defaultPassword(params::UserLevel::Operator)); // T3's Z is param 932 (issue 26)
    answer(panel, "5");
    auto s = panel.session().latest();
    EXPECT_NEAR(s->status.work(2), 5.0, 1e-6) << "the work Z shown (the offset is kept to 1e-6 mm)";
    EXPECT_NEAR(parameter(panel, 932), s->status.machine(2) - s->status.workOffsets[1](2) - 5.0, 1e-6);
    EXPECT_EQ(page->cellText(2, Column::Z), QString::number(parameter(panel, 932), 'f', 3));
}

TEST(ToolTablePage, TouchOffWithAnEmptySpindleIsRefused) {
    ui::MachineSession::Options options;
    options.tool = 0;
    PanelHarness panel(options);
    ASSERT_NE(openTable(panel), nullptr);
    panel.softkey(4);
    EXPECT_FALSE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("当前刀具号为0或非法,操作无效!")))
        << panel.window().messageText().toStdString();
}

TEST(ToolTablePage, ALinuxCncFileImportsAsItIsTheTableExportsAndBothSurviveARestart) {
    QTemporaryDir dir;
    QString error;
    auto folder = ui::copyBundledMachine(dir.path(), &error);
    ASSERT_TRUE(folder) << error.toStdString();
    const QByteArray linuxCnc = ";from the LinuxCNC router\n"
                                "T1 P1 Z+60.000000 D+6.000000 ;6 mm end mill {rpm=24000 teeth=2 type=flat}\n"
                                "T5 P5 Z-12.5 S100 ;a word LinuxCNC does not know\n"
                                "T7 P7 Z55.25 ;drill\n";
    putFile(QDir(dir.path()).filePath("router.tbl"), linuxCnc);
    {
        PanelHarness panel(*folder);
        ui::ToolTablePage* page = openTable(panel);
        ASSERT_NE(page, nullptr);
        panel.softkey(5);
        answer(panel, "../router.tbl");
        const QString question = panel.window().prompt()->question();
        EXPECT_TRUE(question.contains(QStringLiteral("router.tbl:3:14"))) << question.toStdString();
        panel.key("ENTER");
        EXPECT_EQ(page->rowCount(), 2);
        EXPECT_EQ(parameter(panel, 930), 60.0);
        EXPECT_EQ(parameter(panel, 931), 0.0) << "T2 is not in the imported table";
        EXPECT_EQ(parameter(panel, 973), 0.0) << "nor the virtual T17";
        EXPECT_EQ(fileText(QDir(*folder).filePath("tool.tbl")), QString::fromUtf8(linuxCnc))
            << "the file as the user wrote it, the skipped line too";
        panel.key("DOWN");
        panel.softkey(3);
        panel.key("ENTER");
        EXPECT_EQ(page->rowCount(), 1);
        panel.softkey(6);
        answer(panel, "export.tbl");
        EXPECT_EQ(fileText(QDir(*folder).filePath("export.tbl")),
                  QStringLiteral(";from the LinuxCNC router\n"
                                 "T1 P1 Z+60.000000 D+6.000000 ;6 mm end mill {rpm=24000 teeth=2 type=flat}\n"
                                 "T5 P5 Z-12.5 S100 ;a word LinuxCNC does not know\n"));
    }
    PanelHarness again(*folder);
    ui::ToolTablePage* page = openTable(again);
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(page->rowCount(), 1);
    EXPECT_EQ(page->cellText(0, Column::Rpm), QStringLiteral("24000"));
    EXPECT_EQ(parameter(again, 930), 60.0);
}

// Issue 26: the export never lands on the loaded program, and a FIFO the operator names is
// written as a FIFO, not renamed over.
TEST(ToolTablePage, TheExportRefusesTheLoadedProgramAndWritesAFifoAsAFifo) {
    PanelHarness panel;
    QTemporaryDir dir;
    panel.loadProgram("prog.nc", "G0 X1\nM30\n");
    const QString program = panel.session().latest()->programFile;
    ui::ToolTablePage* page = openTable(panel);
    ASSERT_NE(page, nullptr);
    panel.softkey(6);
    answer(panel, program);
    EXPECT_TRUE(panel.window().messageText().contains(program)) << panel.window().messageText().toStdString();
    QFile file(program);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll(), "G0 X1\nM30\n");

    const QString fifo = dir.filePath("tools.fifo");
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
    auto reader = std::async(std::launch::async, [fifo] {
        QFile in(fifo);
        return in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
    });
    panel.softkey(6);
    answer(panel, fifo);
    ASSERT_EQ(reader.wait_for(std::chrono::seconds(30)), std::future_status::ready);
    EXPECT_TRUE(reader.get().contains("T1 P1")) << panel.window().messageText().toStdString();
    struct stat s {};
    ASSERT_EQ(::stat(fifo.toLocal8Bit().constData(), &s), 0);
    EXPECT_TRUE(S_ISFIFO(s.st_mode));
}

} // namespace m350::test
