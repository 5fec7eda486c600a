// The Program page and its editor, driven as an operator drives them: the file list and its
// refusals, editing and saving (in the file's own encoding), the parser's findings as they are
// typed, a run followed in the editor, and 仿真 beside the machine.
#include "tests/ui/PanelHarness.h"

#include "ui/pages/ProgramPage.h"
#include "ui/panel/PromptBox.h"
#include "ui/panel/SoftkeyBar.h"
#include "ui/panel/StatusLine.h"
#include "ui/program/CodeView.h"
#include "ui/program/ProgramChecker.h"
#include "ui/program/ProgramEditor.h"
#include "ui/program/ProgramList.h"
#include "ui/program/SimulationPanel.h"

#include "core/config/MachineConfig.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QStringEncoder>
#include <QTest>

#include <filesystem>

namespace m350::test {

namespace {

QString programs(const PanelHarness& panel) { return QDir(panel.folder()).filePath("programs"); }

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

QByteArray readFile(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

ui::ProgramPage* openProgramPage(PanelHarness& panel) {
    panel.key("PROGRAM");
    return panel.page<ui::ProgramPage>();
}

// Selects `name` with the DOWN key, as the operator would.
void selectFile(PanelHarness& panel, ui::ProgramPage* page, const QString& name) {
    page->list()->refresh();
    for (int i = 0; i < 50 && page->list()->selectedName() != name; ++i) {
        panel.key(i == 0 ? "UP" : "DOWN");
    }
    ASSERT_EQ(page->list()->selectedName(), name);
}

bool checked(ui::ProgramPage* page) {
    return QTest::qWaitFor([page] { return !page->editor()->checker()->pending(); }, 10000);
}

} // namespace

TEST(ProgramPage, TheLocalDiskListsTheBundledExampleAndItsSoftkeys) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    ASSERT_NE(page, nullptr);
    EXPECT_TRUE(page->list()->names().contains("manual-test-program.nc"));
    EXPECT_TRUE(panel.window().softkeys()->label(1).contains(QStringLiteral("切换磁盘")));
    EXPECT_TRUE(panel.window().softkeys()->label(9).contains(QStringLiteral("仿真")));
    panel.softkey(1); // 切换磁盘: the U disk, then the system disk with the macro libraries
    panel.softkey(1);
    EXPECT_EQ(page->list()->disk(), ui::ProgramFiles::Disk::System);
    EXPECT_TRUE(page->list()->names().contains("slib-g.nc"));
    EXPECT_FALSE(panel.window().softkeys()->enabled(2)); // no 删除 of a library
}

TEST(ProgramPage, EditSaveAndReloadAProgram) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("part.nc"), "G0 X1\nM30\n");
    selectFile(panel, page, "part.nc");
    panel.softkey(10); // NC读取
    EXPECT_TRUE(panel.session().latest()->programFile.endsWith("part.nc"));
    panel.softkey(6); // 编辑
    ASSERT_EQ(page->mode(), ui::ProgramPage::Mode::Editor);
    panel.key("DOWN"); // to line 2, before M30
    panel.type("G0 Y2");
    panel.key("ENTER");
    EXPECT_TRUE(page->editor()->modified());
    panel.softkey(1); // 保存退出
    EXPECT_EQ(page->mode(), ui::ProgramPage::Mode::List);
    EXPECT_EQ(readFile(QDir(programs(panel)).filePath("part.nc")), "G0 X1\nG0 Y2\nM30\n");
    panel.key("START"); // the saved text is what runs
    panel.advance(10.0);
    EXPECT_NEAR(panel.session().latest()->status.work(0), 1.0, 1e-6);
    EXPECT_NEAR(panel.session().latest()->status.work(1), 2.0, 1e-6);
    EXPECT_EQ(panel.session().latest()->status.run, controller::PanelStatus::Run::Finished);
    panel.softkey(6);
    EXPECT_EQ(page->editor()->view()->toPlainText(), "G0 X1\nG0 Y2\nM30\n");
}

TEST(ProgramPage, EscAsksBeforeDroppingAnEdit) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("keep.nc"), "M30\n");
    selectFile(panel, page, "keep.nc");
    panel.key("ENTER");
    panel.type("G4 P1");
    panel.key("ESC");
    ASSERT_TRUE(panel.window().prompt()->active());
    panel.key("ESC"); // [退出]不保存
    EXPECT_EQ(page->mode(), ui::ProgramPage::Mode::List);
    EXPECT_EQ(readFile(QDir(programs(panel)).filePath("keep.nc")), "M30\n");
}

TEST(ProgramPage, ASyntaxErrorIsMarkedAtItsLineAndGoesWhenFixed) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("check.nc"), "G0 X1\nM30\n");
    selectFile(panel, page, "check.nc");
    panel.key("ENTER");
    ASSERT_TRUE(checked(page));
    EXPECT_TRUE(page->editor()->view()->marks().isEmpty());
    panel.key("DOWN");
    panel.type("G1 X[1+");
    panel.key("ENTER");
    ASSERT_TRUE(checked(page));
    ASSERT_FALSE(page->editor()->view()->marks().isEmpty());
    EXPECT_EQ(page->editor()->view()->marks().front().line, 2);
    EXPECT_GT(page->editor()->view()->marks().front().column, 0);
    panel.key("UP");
    panel.softkey(3); // 删除行
    ASSERT_TRUE(checked(page));
    EXPECT_TRUE(page->editor()->view()->marks().isEmpty());
    EXPECT_EQ(page->editor()->view()->toPlainText(), "G0 X1\nM30\n");
}

// The editor parses as the machine's controller does: once parameter 6050 makes G100 a macro call,
// `G100X1.E2.` passes X and the argument E as G65 would, and the editor marks nothing; on the plain
// fanuc-0i the same line is the number 1.E2., which it marks where the run would refuse it.
TEST(ProgramPage, TheEditorParsesWithTheMachinesMacroCallCodes) {
    for (const bool called : {false, true}) {
        QTemporaryDir dir;
        const std::filesystem::path folder = std::filesystem::path(dir.path().toStdString()) / "fanuc-0i";
        std::filesystem::copy(config::bundledMachinesDirectory() + "/fanuc-0i", folder,
                              std::filesystem::copy_options::recursive);
        if (called) {
            QFile params(QString::fromStdString((folder / "params.toml").string()));
            ASSERT_TRUE(params.open(QIODevice::Append));
            params.write("6050 = 100  # G100 calls O9010\n");
        }
        PanelHarness panel(QString::fromStdString(folder.string()));
        auto* page = openProgramPage(panel);
        ASSERT_NE(page, nullptr);
        writeFile(QDir(programs(panel)).filePath("call.nc"), "G100X1.E2.\nM30\n");
        selectFile(panel, page, "call.nc");
        panel.key("ENTER");
        ASSERT_TRUE(checked(page));
        const QVector<ui::CodeView::Mark> marks = page->editor()->view()->marks();
        if (called) {
            EXPECT_TRUE(marks.isEmpty()) << marks.front().message.toStdString();
        } else {
            ASSERT_FALSE(marks.isEmpty());
            EXPECT_EQ(marks.front().line, 1);
            EXPECT_EQ(marks.front().column, 6);
        }
    }
}

TEST(ProgramPage, AGbkFileIsSavedInGbk) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    QStringEncoder gbk("GB18030");
    ASSERT_TRUE(gbk.isValid());
    const QString original = QStringLiteral("(换刀测试)\r\nT1 //1号刀\r\nM30\r\n");
    const QByteArray bytes = gbk.encode(original);
    writeFile(QDir(programs(panel)).filePath("gbk.nc"), bytes);
    selectFile(panel, page, "gbk.nc");
    panel.key("ENTER");
    EXPECT_EQ(page->editor()->encoding(), ui::SourceFile::Encoding::Gbk);
    panel.type(QStringLiteral("(主轴)"));
    panel.key("ENTER");
    panel.softkey(1);
    QStringEncoder again("GB18030");
    EXPECT_EQ(readFile(QDir(programs(panel)).filePath("gbk.nc")),
              QByteArray(again.encode(QStringLiteral("(主轴)\r\n") + original)));
}

// Old Mac files and some panel exports end lines with CR alone: the editor shows the lines the
// parser reads and writes CR back.
TEST(ProgramPage, ACrOnlyFileShowsItsLinesAndKeepsItsLineEnds) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("cr.nc"), "G0 X1\rG0 X\rM30\r");
    selectFile(panel, page, "cr.nc");
    panel.key("ENTER");
    EXPECT_EQ(page->editor()->view()->toPlainText(), "G0 X1\nG0 X\nM30\n");
    ASSERT_TRUE(checked(page));
    ASSERT_FALSE(page->editor()->view()->marks().isEmpty());
    EXPECT_EQ(page->editor()->view()->marks().front().line, 2);
    panel.type(QStringLiteral("(a)"));
    panel.key("ENTER");
    panel.softkey(1);
    EXPECT_EQ(readFile(QDir(programs(panel)).filePath("cr.nc")), QByteArray("(a)\rG0 X1\rG0 X\rM30\r"));
}

TEST(ProgramPage, NewRenameAndDeleteWithTheirRefusals) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    const QDir dir(programs(panel));
    panel.softkey(5); // 新建
    ASSERT_TRUE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().prompt()->question().contains(QStringLiteral("请输入文件名")));
    panel.type("manual-test-program.nc");
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().prompt()->question().contains(QStringLiteral("文件名存在请重新输入")));
    panel.key("ESC");
    panel.softkey(5);
    panel.type(QString(40, QLatin1Char('a')));
    panel.key("ENTER");
    EXPECT_TRUE(panel.window().prompt()->question().contains(QStringLiteral("文件名过长")));
    panel.key("ESC");
    panel.softkey(5);
    panel.type("new.nc");
    panel.key("ENTER");
    EXPECT_TRUE(dir.exists("new.nc"));
    EXPECT_EQ(page->mode(), ui::ProgramPage::Mode::Editor);
    panel.key("ESC"); // nothing typed: no question
    EXPECT_EQ(page->mode(), ui::ProgramPage::Mode::List);
    selectFile(panel, page, "new.nc");
    panel.softkey(3); // 重命名
    for (int i = 0; i < 6; ++i) {
        panel.key("BACKSPACE");
    }
    panel.type("renamed.nc");
    panel.key("ENTER");
    EXPECT_FALSE(dir.exists("new.nc"));
    EXPECT_TRUE(dir.exists("renamed.nc"));
    EXPECT_EQ(page->list()->selectedName(), "renamed.nc");
    panel.softkey(2); // 删除: 是否删除当前选中文件?
    EXPECT_TRUE(panel.window().prompt()->question().contains(QStringLiteral("是否删除当前选中文件")));
    panel.key("ESC");
    EXPECT_TRUE(dir.exists("renamed.nc"));
    panel.softkey(2);
    panel.key("ENTER");
    EXPECT_FALSE(dir.exists("renamed.nc"));
}

TEST(ProgramPage, ARunningFileIsNotDeletedAndItsRunningLineMovesInTheEditor) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("run.nc"), "G91 G1 X10 F600\nG1 Y10\nG1 X-10\nG1 Y-10\nM30\n");
    selectFile(panel, page, "run.nc");
    panel.softkey(10); // NC读取
    panel.key("START");
    panel.advance(0.3);
    panel.softkey(2); // 删除 while it runs: 加工区文件不可删除!
    EXPECT_FALSE(panel.window().prompt()->active());
    EXPECT_TRUE(panel.window().messageText().contains(QStringLiteral("不可删除")));
    panel.softkey(6); // 编辑
    panel.advance(0.1);
    const int first = page->editor()->view()->runningLine();
    EXPECT_EQ(first, 1);
    EXPECT_TRUE(page->editor()->view()->isReadOnly());
    panel.advance(1.5);
    EXPECT_GT(page->editor()->view()->runningLine(), first)
        << static_cast<int>(panel.session().latest()->status.run) << " " << panel.session().latest()->status.file << ":"
        << panel.session().latest()->status.line << " " << panel.window().messageText().toStdString();
    panel.advance(10.0);
    EXPECT_EQ(page->editor()->view()->runningLine(), 0);
    EXPECT_FALSE(page->editor()->view()->isReadOnly());
}

TEST(ProgramPage, SimulationDrawsThePathWhileTheMachineStaysWhereItIs) {
    PanelHarness panel;
    auto* page = openProgramPage(panel);
    writeFile(QDir(programs(panel)).filePath("sim.nc"),
              "G90 G0 X0 Y0\nG1 X20 F600\nG3 X20 Y20 I0 J10\nG1 X0\nG1 Y0\nM30\n");
    const auto before = panel.session().latest()->status.machine;
    selectFile(panel, page, "sim.nc");
    panel.softkey(9); // 仿真
    ASSERT_EQ(page->mode(), ui::ProgramPage::Mode::Simulation);
    panel.softkey(1); // speed x1
    panel.advance(0.5);
    EXPECT_EQ(panel.window().statusLine()->modeText(), QStringLiteral("仿真"));
    const int line = page->simulation()->code()->runningLine();
    const std::size_t points = page->simulation()->points();
    EXPECT_GE(line, 1);
    panel.advance(2.5);
    EXPECT_GT(page->simulation()->code()->runningLine(), line);
    EXPECT_GT(page->simulation()->points(), points);
    panel.softkey(4); // as fast as the core goes: to the end at once
    panel.advance(0.1);
    EXPECT_EQ(panel.session().latest()->simulation.run, ui::SimulationView::Run::Finished);
    EXPECT_GT(page->simulation()->points(), 20U); // the arc in chords
    EXPECT_TRUE((panel.session().latest()->status.machine - before).isZero(1e-9));
    panel.key("ESC");
    EXPECT_EQ(page->mode(), ui::ProgramPage::Mode::List);
    EXPECT_FALSE(panel.session().latest()->simulation.active());
}

TEST(ProgramChecker, FindsTheLineOfAnErrorWithTheMachinesLibraries) {
    auto loaded = config::loadMachineFolder(
        QDir(QString::fromStdString(config::bundledMachinesDirectory())).filePath("m350-linear16").toStdString());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const auto& machine = std::get<config::MachineConfig>(loaded);
    auto marks = ui::ProgramChecker::diagnose(*machine.dialect, machine.libraries, "t.nc", "T1\nM98 P20000\nG1 X[\n");
    ASSERT_EQ(marks.size(), 1) << marks.front().message.toStdString();
    EXPECT_EQ(marks.front().line, 3);
    EXPECT_TRUE(ui::ProgramChecker::diagnose(*machine.dialect, machine.libraries, "t.nc", "M98 P777\n").size() == 1);
}

// Issue 28: the editor warns as `check --lint` does, at the line and column of the mistake.
TEST(ProgramChecker, WarnsAboutAnOutputLeftOnInATraineesMacro) {
    auto loaded = config::loadMachineFolder(
        QDir(QString::fromStdString(config::bundledMachinesDirectory())).filePath("m350-linear16").toStdString());
    ASSERT_TRUE(std::holds_alternative<config::MachineConfig>(loaded));
    const auto& machine = std::get<config::MachineConfig>(loaded);
    const QString wrong = "G0 X0\n#1552=1\nIF [#1521 EQ 1] GOTO9\n#1552=0\nN9 M30\n";
    auto marks = ui::ProgramChecker::diagnose(*machine.dialect, machine.libraries, "t.nc", wrong);
    ASSERT_EQ(marks.size(), 1);
    EXPECT_EQ(marks.front().line, 2);
    EXPECT_EQ(marks.front().column, 1);
    EXPECT_TRUE(marks.front().message.contains("#1552")) << marks.front().message.toStdString();
    EXPECT_TRUE(marks.front().message.contains("5")) << marks.front().message.toStdString();
    const QString right = "G0 X0\n#1552=1\nIF [#1521 EQ 1] GOTO9\n#1552=0\nM30\nN9 #1552=0\nM30\n";
    EXPECT_TRUE(ui::ProgramChecker::diagnose(*machine.dialect, machine.libraries, "t.nc", right).isEmpty());
}

} // namespace m350::test
