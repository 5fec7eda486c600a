#pragma once

#include "core/machine/ToolWorld.h"

#include "ui/session/PanelSnapshot.h"
#include "ui/session/UserAccess.h"

#include "core/config/HookFiles.h"
#include "core/controller/RunSettings.h"
#include "core/tools/ToolTable.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>
#include <QVector>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace m350::config {
struct MachineConfig;
}
namespace m350::controller {
class Controller;
}

namespace m350::ui {

class SessionWorker;

// The one machine behind the panel. The controller lives in a worker thread; every method here
// only queues a call to it and returns at once, so no widget ever blocks on the machine. What the
// machine looks like arrives as snapshots (snapshotReady) at up to 60 Hz.
class MachineSession : public QObject {
    Q_OBJECT
public:
    enum class Clock {
        RealTime, // virtual time follows the wall clock (times `rate`), ticked at 60 Hz
        Manual,   // virtual time moves only by advance(): replays and tests
    };
    struct Options {
        Clock clock = Clock::RealTime;
        double rate = 1.0;     // virtual seconds per wall second (faster for simulation)
        bool homed = true;     // start with every axis homed (--unhomed: as after power-on)
        std::optional<int> tool;
        std::vector<machine::ToolBreak> toolBreaks; // --break: tools that break in the simulated world
        // --dprnt-limit: the most bytes of DPRNT output dprnt.txt keeps (the first and the last records)
        std::uint64_t externalOutputLimit = controller::RunSettings{}.externalOutputLimit;
        // Manual clock only: the machine runs in the panel's own thread, its calls queued to the
        // panel's event loop in the same order, so a headless replay hands nothing between threads
        // (two thread switches an action cost more than the action on a busy machine).
        bool panelThread = false;
    };
    MachineSession(config::MachineConfig config, Options options, QObject* parent = nullptr);
    ~MachineSession() override;

    // the cycle keys
    void start();         // START: resume a hold, or run the loaded program from its beginning
    void pause();         // PAUSE (暂停)
    void reset();         // RESET (复位)
    void emergencyStop(); // E-stop (急停)
    void loadProgram(const QString& path);
    void runMdi(const QStringList& lines, Activity activity = Activity::Mdi);
    void runMdiPageLine(const QString& line); // the MDI page: written into mdi.nc, which runs
    void answerDialog(bool enter);
    // The operator enters the tool the spindle holds (after a stop in a change: Controller::toolDoubt).
    void setSpindleToolNumber(int tool);
    void pressExternStart();
    // A key or softkey that has a hook file (core/config/HookFiles.h): each step runs its hook when
    // the machine folder has one, else its fallback MDI lines (the built-in behaviour), with
    // `variables` set first either way; the next step starts when one ends without an alarm.
    struct HookStep {
        config::Hook hook;
        std::map<int, double> variables;
        QStringList fallback;
    };
    void runHooks(const QVector<HookStep>& steps, Activity activity);
    // K1-K7: what params 210-216 make of them (key-N.nc, an output, a panel key).
    void userKey(int key);
    // FUNC K01-K14 of the 定制功能 page: ext_button.nc with #1996 = M250-M263, or that M code.
    void functionKey(int key);

    // manual work
    // 回机械原点 (empty: all axes): fndzero.nc / fndX.nc .. when the machine folder has it, else
    // every axis with a home switch (or the one given) at once
    void home(const QVector<int>& axes);
    void zeroAxes(const QVector<int>& axes); // 清零: the current position becomes work zero
    void setWorkPosition(int axis, double value); // 坐标管理 / 分中: the current position gets this work coordinate
    void setVariable(int number, double value);   // #50-#499, the offsets #800-#844 ...
    void clearWorkRecord();                       // 清除加工记录: the counters and the run times
    // 断点加工 (SessionWorkerBreakRun.cpp): the loaded file from a line (指定行加工), again at the block
    // the last 暂停 stopped (暂停断点加工), at the break point kept in the machine folder (断电断点加工)
    void startAtLine(int line);
    void resumeAtPause();
    void powerResume();
    void jogPress(int axis, int direction);
    void jogRelease(int axis);
    void cycleJogMode(); // CONT -> STEP -> MPG
    void setJogStep(double distance);
    void toggleJogHighSpeed(); // Hi/Lo
    void wheel(int axis, int multiplier, int detents, double seconds);
    void toggleHandwheelGuide(); // MPG RUN (试切)
    void setGuideRetrace(bool retrace);
    void feedOverrideKey(int step);    // 0: 100 %, +10 / -10
    void spindleOverrideKey(int step); // 0: 100 %, +10 / -10
    void spindleKey(int code);         // the M-code keys 3 4 5 8 9 10 11 19 (their hooks); 0 = SPINDLE (toggle)

    // IO page and parameters
    void setOutput(int port, int level);
    void setParameter(int number, double value);
    enum class Fault { None, Stuck, Slow, Bouncing, Pressed }; // Pressed: `level` for `seconds`, once
    void forceInput(int pin, Fault fault, int level, double seconds);
    // 参数恢复: every value at once, one write of params.toml (setParameter writes it each time).
    void setParameters(const std::map<int, double>& values);
    // 刀具表 (the tool table page): a row added or replaced, taken out, the whole table from an
    // imported file (`from` names it for the log), and touch off of the loaded tool at work Z.
    void putTool(const tools::ToolEntry& entry);
    void removeTool(int tool);
    void replaceToolTable(const tools::ToolTable& table, const QString& from);
    void touchOffTool(double workZ);
    // 刀具寿命: the operator's reset (counter clear) of a tool life group's used life.
    void resetToolLife(int group);
    // The #50-#499 view: while on, each snapshot carries those variables (userVariables).
    void watchVariables(bool on);
    // A page that draws the machine (the 图形显示 view): while on, each snapshot carries the
    // machine's scene; building it at every snapshot for nobody cost a replay a tenth of its time.
    void watchScene(bool on);

    // 用户权限 (the panel's, not the machine's: answered here at once); snapshots carry the level for
    // the status line from the next frame on.
    params::UserLevel userLevel() const { return access_.level(); }
    bool login(params::UserLevel level, const QString& password);
    std::optional<QString> changePassword(const QString& password);
    // Why passwords.toml locks every level above Guest (UserAccess::problem), empty when sound.
    const QString& passwordsProblem() const { return access_.problem(); }

    // 仿真: runs the file on a second controller beside the machine (which never moves); speed in
    // virtual seconds per wall second, 0 = as fast as the core goes. snapshot.simulation shows it.
    void startSimulation(const QString& path, double speed);
    void setSimulationSpeed(double speed);
    void stopSimulation();

    // Manual clock: lets `seconds` of virtual time pass in frames of at most 1/60 s and waits until
    // the worker has done so; the snapshot of the last frame is then queued to this thread.
    void advance(double seconds);
    // Manual clock: the same frames, but while the machine is quiet (nothing runs, holds, jogs or
    // simulates) they pass without a snapshot each, so idle virtual time costs next to nothing; one
    // snapshot at the end (none with `publishAtEnd` false while still quiet: more time passes next).
    // Returns the time that passed (0: not quiet, use advance()).
    double advanceWhileQuiet(double seconds, bool publishAtEnd = true);
    // Waits until every call queued so far has run (replays and tests).
    void sync();
    // With the machine in the panel's thread: whether no call has reached the machine since its
    // last snapshot, so that a snapshot now would say the same. False with the machine in its own
    // thread (its clock publishes on its own there).
    bool unchangedSinceSnapshot() const { return panelThread_ && calls_ == callsAtSnapshot_; }
    // Runs `look` on the controller in its thread after every call queued so far, and waits: how a
    // training attempt's end is read for grading (core/training/FactsFromController.h).
    void examine(const std::function<void(controller::Controller&)>& look);

    SnapshotPtr latest() const { return latest_; }

signals:
    void snapshotReady(m350::ui::SnapshotPtr snapshot);

private:
    void post(std::function<void(SessionWorker&)> call);
    // Runs `call` in the worker after every call posted before it, and waits for it.
    void runNow(const std::function<void(SessionWorker&)>& call);
    QThread thread_;
    bool panelThread_ = false;
    std::uint64_t calls_ = 0;           // calls that reached the worker (posted or run)
    std::uint64_t callsAtSnapshot_ = 0; // calls_ when the worker last published (panel thread only)
    SessionWorker* worker_ = nullptr;
    SnapshotPtr latest_;
    UserAccess access_;
    QString loggedPasswordsProblem_; // what the System Log last heard of passwords.toml
    void logPasswordsProblem();
};

} // namespace m350::ui
