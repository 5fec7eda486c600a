#include "ui/session/MachineSession.h"

#include "ui/session/SessionWorker.h"

#include "core/config/MachineConfig.h"

#include <QCoreApplication>
#include <QEvent>
#include <QMetaObject>

#include <algorithm>
#include <cmath>

namespace m350::ui {

MachineSession::MachineSession(config::MachineConfig config, Options options, QObject* parent)
    : QObject(parent), access_(QString::fromStdString(config.folder)) {
    qRegisterMetaType<SnapshotPtr>();
    panelThread_ = options.panelThread && options.clock == Clock::Manual;
    worker_ = new SessionWorker(std::move(config), options);
    // queued in either case: a snapshot reaches the panel when its event loop next runs
    connect(
        worker_, &SessionWorker::published, this,
        [this](const SnapshotPtr& snapshot) {
            latest_ = snapshot;
            emit snapshotReady(snapshot);
        },
        Qt::QueuedConnection);
    if (panelThread_) {
        connect(worker_, &SessionWorker::published, this, [this] { callsAtSnapshot_ = calls_; }, Qt::DirectConnection);
    } else {
        worker_->moveToThread(&thread_);
        thread_.setObjectName("machine");
        thread_.start();
    }
    post([](SessionWorker& w) { w.begin(); });
    logPasswordsProblem();
}

// The System Log hears when passwords.toml locks the levels (at start, or found at a login), once
// each time the fault changes.
void MachineSession::logPasswordsProblem() {
    if (access_.problem() == loggedPasswordsProblem_) {
        return;
    }
    loggedPasswordsProblem_ = access_.problem();
    if (!loggedPasswordsProblem_.isEmpty()) {
        post([problem = loggedPasswordsProblem_](SessionWorker& w) { w.recordLog("passwords_locked", problem); });
    }
}

MachineSession::~MachineSession() {
    runNow([](SessionWorker& w) { w.finish(); });
    thread_.quit();
    thread_.wait();
    delete worker_;
}

void MachineSession::post(std::function<void(SessionWorker&)> call) {
    ++calls_;
    QMetaObject::invokeMethod(worker_, [w = worker_, call = std::move(call)] { call(*w); }, Qt::QueuedConnection);
}

void MachineSession::runNow(const std::function<void(SessionWorker&)>& call) {
    ++calls_;
    if (panelThread_) {
        QCoreApplication::sendPostedEvents(worker_, QEvent::MetaCall); // what was posted before, in order
        call(*worker_);
        return;
    }
    QMetaObject::invokeMethod(worker_, [w = worker_, &call] { call(*w); }, Qt::BlockingQueuedConnection);
}

void MachineSession::start() { post([](SessionWorker& w) { w.start(); }); }
void MachineSession::pause() { post([](SessionWorker& w) { w.pause(); }); }
void MachineSession::reset() { post([](SessionWorker& w) { w.reset(); }); }
void MachineSession::emergencyStop() { post([](SessionWorker& w) { w.emergencyStop(); }); }
void MachineSession::loadProgram(const QString& path) {
    post([path](SessionWorker& w) { w.loadProgram(path); });
}
void MachineSession::runMdiPageLine(const QString& line) {
    post([line](SessionWorker& w) { w.runMdi({line}, Activity::Mdi, true); });
}

void MachineSession::runMdi(const QStringList& lines, Activity activity) {
    post([lines, activity](SessionWorker& w) { w.runMdi(lines, activity); });
}
void MachineSession::answerDialog(bool enter) { post([enter](SessionWorker& w) { w.answerDialog(enter); }); }
void MachineSession::setSpindleToolNumber(int tool) {
    post([tool](SessionWorker& w) { w.setSpindleToolNumber(tool); });
}
void MachineSession::pressExternStart() { post([](SessionWorker& w) { w.pressExternStart(); }); }
void MachineSession::runHooks(const QVector<HookStep>& steps, Activity activity) {
    post([steps, activity](SessionWorker& w) { w.runHooks(steps, activity); });
}
void MachineSession::userKey(int key) { post([key](SessionWorker& w) { w.userKey(key); }); }
void MachineSession::functionKey(int key) { post([key](SessionWorker& w) { w.functionKey(key); }); }
void MachineSession::home(const QVector<int>& axes) { post([axes](SessionWorker& w) { w.home(axes); }); }
void MachineSession::zeroAxes(const QVector<int>& axes) { post([axes](SessionWorker& w) { w.zeroAxes(axes); }); }
void MachineSession::setWorkPosition(int axis, double value) {
    post([=](SessionWorker& w) { w.setWorkPosition(axis, value); });
}
void MachineSession::setVariable(int number, double value) {
    post([=](SessionWorker& w) { w.setVariable(number, value); });
}
void MachineSession::clearWorkRecord() { post([](SessionWorker& w) { w.clearWorkRecord(); }); }
void MachineSession::startAtLine(int line) { post([line](SessionWorker& w) { w.startAtLine(line); }); }
void MachineSession::resumeAtPause() { post([](SessionWorker& w) { w.resumeAtPause(); }); }
void MachineSession::powerResume() { post([](SessionWorker& w) { w.powerResume(); }); }
void MachineSession::jogPress(int axis, int direction) {
    post([axis, direction](SessionWorker& w) { w.jogPress(axis, direction); });
}
void MachineSession::jogRelease(int axis) { post([axis](SessionWorker& w) { w.jogRelease(axis); }); }
void MachineSession::cycleJogMode() { post([](SessionWorker& w) { w.cycleJogMode(); }); }
void MachineSession::setJogStep(double distance) { post([distance](SessionWorker& w) { w.setJogStep(distance); }); }
void MachineSession::toggleJogHighSpeed() { post([](SessionWorker& w) { w.toggleJogHighSpeed(); }); }
void MachineSession::wheel(int axis, int multiplier, int detents, double seconds) {
    post([=](SessionWorker& w) { w.wheel(axis, multiplier, detents, seconds); });
}
void MachineSession::toggleHandwheelGuide() { post([](SessionWorker& w) { w.toggleHandwheelGuide(); }); }
void MachineSession::setGuideRetrace(bool retrace) { post([retrace](SessionWorker& w) { w.setGuideRetrace(retrace); }); }
void MachineSession::feedOverrideKey(int step) { post([step](SessionWorker& w) { w.feedOverrideKey(step); }); }
void MachineSession::spindleOverrideKey(int step) { post([step](SessionWorker& w) { w.spindleOverrideKey(step); }); }
void MachineSession::spindleKey(int code) { post([code](SessionWorker& w) { w.spindleKey(code); }); }
void MachineSession::setOutput(int port, int level) { post([=](SessionWorker& w) { w.setOutput(port, level); }); }
void MachineSession::setParameter(int number, double value) {
    post([=](SessionWorker& w) { w.setParameter(number, value); });
}
void MachineSession::forceInput(int pin, Fault fault, int level, double seconds) {
    post([=](SessionWorker& w) { w.forceInput(pin, fault, level, seconds); });
}
void MachineSession::setParameters(const std::map<int, double>& values) {
    post([values](SessionWorker& w) { w.setParameters(values); });
}
void MachineSession::putTool(const tools::ToolEntry& entry) {
    post([entry](SessionWorker& w) { w.putTool(entry); });
}
void MachineSession::removeTool(int tool) { post([tool](SessionWorker& w) { w.removeTool(tool); }); }
void MachineSession::replaceToolTable(const tools::ToolTable& table, const QString& from) {
    post([table, from](SessionWorker& w) { w.replaceToolTable(table, from); });
}
void MachineSession::touchOffTool(double workZ) { post([workZ](SessionWorker& w) { w.touchOffTool(workZ); }); }
void MachineSession::resetToolLife(int group) { post([group](SessionWorker& w) { w.resetToolLife(group); }); }
void MachineSession::watchVariables(bool on) { post([on](SessionWorker& w) { w.watchVariables(on); }); }
void MachineSession::watchScene(bool on) { post([on](SessionWorker& w) { w.watchScene(on); }); }
bool MachineSession::login(params::UserLevel level, const QString& password) {
    const bool opened = access_.login(level, password);
    logPasswordsProblem();
    if (!opened) {
        return false;
    }
    post([level = access_.level()](SessionWorker& w) { w.setUserLevel(level); });
    return true;
}

std::optional<QString> MachineSession::changePassword(const QString& password) {
    auto error = access_.changePassword(password);
    logPasswordsProblem();
    return error;
}

void MachineSession::startSimulation(const QString& path, double speed) {
    post([=](SessionWorker& w) { w.startSimulation(path, speed); });
}
void MachineSession::setSimulationSpeed(double speed) { post([=](SessionWorker& w) { w.setSimulationSpeed(speed); }); }
void MachineSession::stopSimulation() { post([](SessionWorker& w) { w.stopSimulation(); }); }

void MachineSession::advance(double seconds) {
    constexpr double kFrame = 1.0 / 60.0;
    while (seconds > 1e-12) {
        double step = std::min(kFrame, seconds);
        runNow([step](SessionWorker& w) { w.advanceManual(step); });
        seconds -= step;
    }
}

double MachineSession::advanceWhileQuiet(double seconds, bool publishAtEnd) {
    double passed = 0.0;
    runNow([seconds, publishAtEnd, &passed](SessionWorker& w) { passed = w.advanceWhileQuiet(seconds, publishAtEnd); });
    return passed;
}

void MachineSession::sync() {
    runNow([this](SessionWorker& w) {
        // in the panel's thread, calls that ended in a snapshot of their own need no second one
        // (panelThread_ first: in the worker's thread the counters are the panel thread's)
        if (!panelThread_ || callsAtSnapshot_ != calls_) {
            w.publish();
        }
    });
}

void MachineSession::examine(const std::function<void(controller::Controller&)>& look) {
    runNow([&look](SessionWorker& w) { look(w.controller()); });
}

} // namespace m350::ui
