#pragma once

#include "ui/session/LogTail.h"
#include "ui/session/PreviewShown.h"
#include "ui/session/SimulationView.h"

#include "core/params/ParameterPages.h"
#include "core/files/SystemLog.h"
#include "core/controller/PanelStatus.h"
#include "core/tools/ToolLifeView.h"
#include "core/controller/SpindleLoadView.h"
#include "core/preview/MachineScene.h"
#include "core/tools/ToolTable.h"

#include <QMetaType>

namespace m350::preview {
struct MachineScene;
}
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>
#include <vector>

namespace m350::ui {

// What the session is doing on the operator's behalf, for the mode field of the status line.
// Hook: a hook file a key or power-on started (K1-K7, sysstart.nc), which the panel shows as AUTO.
enum class Activity { None, Auto, Mdi, Homing, Probe, SpindleKey, Hook };

// 加工统计: what the automatic runs of this session took (the counters are params 201/202).
struct WorkRecord {
    QString file;           // 当前加工程序
    QString startedAt;      // 开始日期时间 of the first run since the record was cleared
    double lastPiece = 0.0; // 单件加工时间 of the last finished run, virtual seconds
    double total = 0.0;     // 总加工时间
    int finished = 0;       // runs finished since the record was cleared
};

// 断点加工: where the last 暂停 stopped the loaded file (line 0: none), and the break point kept in
// the machine folder for 断电断点加工 (it survives a restart).
struct BreakPoints {
    QString pauseFile;
    int pauseLine = 0;
    QString keptFile;
    int keptLine = 0;
};

// One immutable picture of the machine, published by the session from its worker thread. Widgets
// keep the latest one and read nothing else.
struct PanelSnapshot {
    controller::PanelStatus status;
    Activity activity = Activity::None;
    // The session's virtual clock since power-on: it only grows, where status.time (the display's
    // time) stands still or runs back while the 试切 wheel holds or retraces the program.
    double sessionTime = 0.0;
    QString programFile;  // the file START runs (empty: none loaded)
    // The lines the last MDI run was given directly (the run's file is then "MDI"); a new object
    // per run, so the Monitor's program window reads them only when they change.
    std::shared_ptr<const QStringList> mdiLines;
    QString lastError;    // why the last command was refused (syntax error with file:line:col, ...)
    QString machineName;
    QString machineNameZh; // machine.toml's name_zh, empty when it has none
    int magazineCapacity = 0;
    bool homingPrompt = false; // param 127 = 0 and X, Y, Z not homed: 是否进行开机寻零操作?
    SimulationView simulation; // the Program page's 仿真, beside the machine (Off when none)
    // The machine view's previews (ui/session/ProgramPreviews.h): the loaded program's, the 仿真 file's.
    PreviewShown programPreview;
    PreviewShown simulationPreview;
    params::UserLevel userLevel = params::UserLevel::Guest; // 访客 / 操作员 / 管理员 / 超级管理
    QVector<double> userVariables; // #50-#499 while the Param page watches them (NaN: vacant), else empty
    std::shared_ptr<const LogTail> log; // 系统日志, its newest entries, oldest first (shared, never changed)
    WorkRecord workRecord;
    BreakPoints breakPoints;
    // The tool table as it stands (a new object only when it changed), and why the last save of
    // tool.tbl failed (empty when it is saved).
    std::shared_ptr<const tools::ToolTable> toolTable;
    QString toolTableProblem;
    QString logProblem; // why system-log.tsv could not be read or written (SessionLog::problem)
    // Tool life management (core/tools/ToolLifeView.h; a new object only when it changed), why the
    // last save of toollife.txt failed, and whether the T word itself changes the tool (the M350,
    // where the manager is a simulator extra) rather than M06 (FANUC).
    std::shared_ptr<const tools::LifeView> toolLife;
    QString toolLifeProblem;
    bool tWordChangesTool = false;
    // The breakage monitor's spindle load (a new object only when a sample came or the tool
    // changed); null on a machine without a spindle load model.
    std::shared_ptr<const controller::SpindleLoadView> spindleLoad;
    // What the machine view (图形显示) draws besides the path and the spindle's position
    // (core/preview/MachineScene.h): a new object only when it changed.
    std::shared_ptr<const preview::MachineScene> scene;
    qint64 publishedNs = 0;    // steady clock when the worker published it (the panel's latency meter)
};

using SnapshotPtr = std::shared_ptr<const PanelSnapshot>;

} // namespace m350::ui

Q_DECLARE_METATYPE(m350::ui::SnapshotPtr)
