#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"
#include "ui/program/ProgramFiles.h"

#include "core/config/MachineConfig.h"

#include <QStackedWidget>

namespace m350::ui {

class ProgramEditor;
class ProgramList;
class SimulationPanel;

// 文件管理 Program: the file list of the local disk, the U disk and the system disk (ProgramFiles),
// with 切换磁盘 删除 重命名 拷贝到U盘 新建 编辑 ‖ 拷贝文件 粘贴文件 仿真 NC读取 清除本地 排序 (msg 324-335);
// the editor (保存退出 查找行 删除行, msg 336-341); and 仿真, the file run beside the machine with
// its path drawn. File operations are in ProgramPageFiles.cpp.
class ProgramPage : public Page {
    Q_OBJECT
public:
    enum class Mode { List, Editor, Simulation };
    explicit ProgramPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::program; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    bool typed(const QString& text) override;
    void render(const PanelSnapshot& snapshot) override;
    bool rendersEverySnapshot() const override { return true; }
    // the editor scrolls to its cursor, the simulation's view fits its path: the file list does not
    bool readsLayout() const override { return mode_ != Mode::List; }
    bool drawsMachine() const override { return true; } // the simulation's view, beside the machine
    void retranslate() override;
    QJsonObject state() const override;

    Mode mode() const { return mode_; }
    ProgramList* list() const { return list_; }
    ProgramEditor* editor() const { return editor_; }
    SimulationPanel* simulation() const { return simulation_; }
    // The U disk's folder (--programs DIR; the home folder by default).
    void setUserFolder(const QString& folder);
    // The folder a disk lists: 本地 the machine folder's programs/, U盘 the user's, 系统 the
    // machine folder's *.nc (a replay's `load` may open only these).
    QString folderOf(ProgramFiles::Disk disk) const;
    // Opens `path` in the editor with `line` current (the machine view's click on a move).
    void editAt(const QString& path, int line);
    static constexpr double kSpeeds[] = {1.0, 10.0, 100.0, 0.0}; // 0: as fast as the core goes

private:
    QVector<Softkey> listSoftkeys() const;
    void listSoftkey(int number);
    void editorSoftkey(int number);
    void simulationSoftkey(int number);
    void setMode(Mode mode);
    void showDisk(ProgramFiles::Disk disk);
    ProgramFiles::Sort sortOrder() const;
    void openEditor(const QString& path);
    void closeEditor(bool save);
    void findLine();
    void startSimulation(const QString& path);
    bool busyWith(const QString& path) const;
    // ProgramPageFiles.cpp: the list's file softkeys
    void newFile();
    void deleteFile();
    void renameFile();
    void copyToOtherDisk();
    void pasteFile();
    void copyInto(const QString& from, const QString& folder, bool selectCopy);
    void clearLocal();
    void askName(const QString& question, const QString& initial, const QString& folder,
                 std::function<void(const QString&)> done);
    QString nameProblemText(ProgramFiles::NameProblem problem) const;

    config::MachineConfig machine_; // for the dialect and the macro libraries
    // the dialect as the controller parses this machine's programs: its macro-call codes take
    // arguments as G65 does (config::parsingDialect), so the editor marks what a run would refuse
    gcode::Dialect parsing_;
    QStackedWidget* stack_;
    ProgramList* list_;
    ProgramEditor* editor_;
    SimulationPanel* simulation_;
    Mode mode_ = Mode::List;
    QString userFolder_;
    QString localFolder_;
    QString clipboard_;     // 拷贝文件 .. 粘贴文件
    double speed_ = 10.0;   // of the next simulation
    SnapshotPtr snapshot_;
};

} // namespace m350::ui
