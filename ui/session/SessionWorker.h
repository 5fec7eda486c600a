#pragma once

#include "ui/session/MachineSession.h"
#include "ui/session/BreakPointFile.h"
#include "ui/session/ExternalOutputFile.h"
#include "ui/session/MachineEventLog.h"
#include "ui/session/SessionLog.h"
#include "ui/session/SimulationSide.h"
#include "ui/session/ToolDataFiles.h"

#include "core/config/MachineFolder.h"
#include "core/params/ParameterTable.h"
#include "core/controller/KeyPress.h"
#include "core/preview/MachineScene.h"
#include "core/tools/ToolData.h"

#include <QObject>

#include <memory>
#include <optional>
#include <utility>

namespace m350::controller {
class Controller;
}

namespace m350::ui {

class FrameClock;

// Lives in the session's worker thread and is, with the SimulationRun its SimulationSide owns,
// the only code of the panel that touches the Controller. Each method runs one operator command,
// then publishes a snapshot.
class SessionWorker : public QObject {
    Q_OBJECT
public:
    SessionWorker(config::MachineConfig config, MachineSession::Options options);
    ~SessionWorker() override;

    void begin();  // in the worker thread: starts the display clock, runs sysstart.nc
    void finish(); // in the worker thread: stops it

    // SessionWorker.cpp: the cycle keys, loading, the Monitor's axis commands, one parameter
    void start();
    void pause();
    void reset();
    void emergencyStop();
    void loadProgram(const QString& path);
    void runMdi(const QStringList& lines, Activity activity, bool throughMdiFile = false);
    void answerDialog(bool enter);
    void setSpindleToolNumber(int tool);
    void pressExternStart();
    void home(const QVector<int>& axes);
    void zeroAxes(const QVector<int>& axes);
    void setWorkPosition(int axis, double value);
    void setVariable(int number, double value);
    void clearWorkRecord();
    void setParameter(int number, double value);
    void advanceManual(double seconds);
    // Manual clock: lets up to `seconds` pass in the same 1/60 s frames while the machine is quiet
    // (quiet()), publishing once at the end (or not: the caller lets more time pass at once) instead
    // of every frame; stops after the frame in which something starts, and publishes it. Returns
    // the time that passed (0 when not quiet).
    double advanceWhileQuiet(double seconds, bool publishAtEnd);
    void publish();
    controller::Controller& controller() { return *controller_; }
    // 仿真 (a SimulationRun beside the machine): speed 0 = as fast as the core goes.
    void startSimulation(const QString& path, double speed);
    void setSimulationSpeed(double speed);
    void stopSimulation();
    // SessionWorkerHooks.cpp: the keys and events that run the machine folder's hook files
    void runHooks(const QVector<MachineSession::HookStep>& steps, Activity activity);
    void userKey(int key);
    void functionKey(int key);
    // 断点加工 (SessionWorkerBreakRun.cpp); a pause or a reset mid-run keeps the break point in the
    // machine folder's `breakpoint` file
    void startAtLine(int line);
    void resumeAtPause();
    void powerResume();
    // SessionWorkerManual.cpp: jog, handwheel, 试切, overrides, spindle keys, the IO page
    void jogPress(int axis, int direction);
    void jogRelease(int axis);
    void cycleJogMode();
    void setJogStep(double distance);
    void toggleJogHighSpeed();
    void wheel(int axis, int multiplier, int detents, double seconds);
    void toggleHandwheelGuide();
    void setGuideRetrace(bool retrace);
    void feedOverrideKey(int step);
    void spindleOverrideKey(int step);
    void spindleKey(int code);
    void setOutput(int port, int level);
    void forceInput(int pin, MachineSession::Fault fault, int level, double seconds);
    // SessionWorkerSettings.cpp: the Param page's batch, the #50-#499 view, the machine's scene,
    // the user level
    void setParameters(const std::map<int, double>& values);
    void watchVariables(bool on);
    void watchScene(bool on);
    void setUserLevel(params::UserLevel level);
    void recordLog(const char* event, const QString& detail) { log_->record(event, detail); }
    // SessionWorkerTools.cpp: the tool table page's edits, import and touch off. Every change of
    // the tool data (these, G10 L1, a macro's #1430, the Param page's 930) is saved to the machine
    // folder's tool.tbl before the next snapshot.
    void putTool(const tools::ToolEntry& entry);
    void removeTool(int tool);
    void replaceToolTable(const tools::ToolTable& table, const QString& from);
    void touchOffTool(double workZ);
    // The 刀具寿命 view's reset of a group's used life; toollife.txt is saved like tool.tbl.
    void resetToolLife(int group);

signals:
    void published(const m350::ui::SnapshotPtr& snapshot);

private:
    // Nothing runs, holds, jogs, simulates or waits to start: a frame changes nothing the panel
    // needs to see at once (devices the IO page switched still move: they show at the next publish).
    bool quiet() const;
    void advance(double seconds);
    bool busy() const;
    void noteAlarm(); // an alarm into the log once (MachineEventLog)
    void refuse(const QString& why);
    QString loadErrors() const; // why the controller's last load failed
    bool loadCurrentFile();
    bool saveParameters(const std::map<int, double>& values); // into params.toml; refuses when it cannot
    void keepParametersTheRunChanged();
    QVector<double> userVariables(); // #50-#499, NaN for a vacant one
    void startedAt(const char* event, bool started, const Message& why);
    void startNextStep();
    void continueSteps(); // after a frame: the next step of runHooks when one ended well
    void panelKey(const QString& key, int code);
    void keyPressed(const controller::KeyPress& press, const QString& key, const QString& hookFile);
    void operatorKeys(); // the keys wired to inputs (extern START, PAUSE, external keys 1-6)
    void powerOn();
    QVector<MachineSession::HookStep> pendingSteps_; // of runHooks, after the one that runs
    Activity stepsActivity_ = Activity::None;
    std::shared_ptr<const QStringList> mdiLines_;
    ToolDataFiles toolData_;
    ExternalOutputFile externalOutput_;
    BreakPointFile breakPointFile_;
    SimulationSide beside_; // 仿真 and the machine view's previews
    std::shared_ptr<const controller::SpindleLoadView> spindleLoad_; // the last published
    std::shared_ptr<const preview::MachineScene> scene_; // the last published (sceneSince)
    void keepBreakPoint(); // after a pause or a reset mid-run
    void keepExternalOutput(bool running); // DPRNT / BPRNT records: the system log and dprnt.txt


    std::unique_ptr<controller::Controller> controller_;
    MachineSession::Options options_;
    QString machineName_;
    QString machineNameZh_;
    FrameClock* frames_ = nullptr; // a real-time clock's frames; a manual clock has none
    Activity activity_ = Activity::None;
    QString programFile_;
    bool fileLoaded_ = false; // the controller holds programFile_ (not MDI lines)
    std::unique_ptr<SessionLog> log_;
    WorkRecord workRecord_;
    MachineEventLog events_; // alarms and parameter changes into the log
    QString lastError_; // why the last command was refused; every command clears it first
    double sessionTime_ = 0.0; // virtual seconds the session has run: only ever grows
    double feedOverride_ = 100.0;
    double spindleOverride_ = 100.0;
    bool jogHigh_ = false;
    config::MachineFolder folder_{std::filesystem::path()}; // the machine folder: every file the session writes there
    params::ParameterTable kept_; // the parameters as params.toml holds them
    bool watchVariables_ = false;
    bool watchScene_ = false;
    params::UserLevel userLevel_ = params::UserLevel::Guest;
};

} // namespace m350::ui
