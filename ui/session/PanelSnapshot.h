#pragma once

#include "ui/session/SimulationView.h"

#include "core/config/ParameterPages.h"
#include "core/controller/PanelStatus.h"

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>

namespace m350::ui {

// What the session is doing on the operator's behalf, for the mode field of the status line.
enum class Activity { None, Auto, Mdi, Homing, Probe, SpindleKey };

// One immutable picture of the machine, published by the session from its worker thread. Widgets
// keep the latest one and read nothing else.
struct PanelSnapshot {
    controller::PanelStatus status;
    Activity activity = Activity::None;
    QString programFile;  // the file START runs (empty: none loaded)
    QString lastError;    // why the last command was refused (syntax error with file:line:col, ...)
    QString machineName;
    int magazineCapacity = 0;
    bool homingPrompt = false; // param 127 = 0 and X, Y, Z not homed: 是否进行开机寻零操作?
    SimulationView simulation; // the Program page's 仿真, beside the machine (Off when none)
    config::UserLevel userLevel = config::UserLevel::Guest; // 访客 / 操作员 / 管理员 / 超级管理
    QVector<double> userVariables; // #50-#499 while the Param page watches them (NaN: vacant), else empty
    qint64 publishedNs = 0;    // steady clock when the worker published it (the panel's latency meter)
};

using SnapshotPtr = std::shared_ptr<const PanelSnapshot>;

} // namespace m350::ui

Q_DECLARE_METATYPE(m350::ui::SnapshotPtr)
