// The keys and events that run the machine folder's hook files (core/config/HookFiles.h): a
// sequence of steps, each its hook or the built-in MDI lines; K1-K7; sysstart.nc at power-on.
#include "ui/session/SessionWorker.h"

#include "ui/session/HookSteps.h"
#include "ui/i18n/Language.h"

#include "core/controller/Controller.h"

namespace m350::ui {

using controller::Controller;

namespace {

// The panel key codes a K key may stand for (params 210-216 above 1000) that act on the machine.
enum PanelKeyCode {
    kGoWorkZero = 1321,
    kGoHome = 1322,
    kReset = 1327,
    kStart = 1328,
    kPause = 1329,
    kSpindle = 1331,
    kM5 = 1370,
    kM4 = 1371,
    kM3 = 1372,
};

const char* logEvent(Activity activity, bool hookRan) {
    switch (activity) {
    case Activity::Probe: return "probe";
    case Activity::Homing: return "home_all";
    default: return hookRan ? "hook" : "mdi";
    }
}

} // namespace

void SessionWorker::runHooks(const QVector<MachineSession::HookStep>& steps, Activity activity) {
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    lastError_.clear();
    pendingSteps_ = steps;
    stepsActivity_ = activity;
    startNextStep();
    publish();
}

void SessionWorker::startNextStep() {
    if (pendingSteps_.isEmpty()) {
        return;
    }
    const MachineSession::HookStep step = pendingSteps_.takeFirst();
    std::vector<std::string> fallback;
    for (const QString& line : step.fallback) {
        fallback.push_back(line.toStdString());
    }
    fileLoaded_ = false;
    const bool hookRan = controller_->hasHook(step.hook);
    if (!controller_->loadHookOrMdi(step.hook, step.variables, fallback)) {
        pendingSteps_.clear();
        lastError_ = loadErrors();
        return;
    }
    if (!controller_->start()) {
        pendingSteps_.clear();
        return;
    }
    activity_ = stepsActivity_;
    log_->record(logEvent(stepsActivity_, hookRan),
                 hookRan ? QString::fromUtf8(config::hookFile(step.hook).fileName.data(),
                                             static_cast<qsizetype>(config::hookFile(step.hook).fileName.size()))
                         : step.fallback.join(QStringLiteral("; ")));
}

// A step that ended without an alarm starts the next one at once (T.nc, then probe.nc); an
// alarm, a reset or E-stop drops the rest.
void SessionWorker::continueSteps() {
    if (pendingSteps_.isEmpty()) {
        return;
    }
    switch (controller_->runState()) {
    case Controller::RunState::Finished: startNextStep(); break;
    case Controller::RunState::Running:
    case Controller::RunState::Hold: break;
    case Controller::RunState::Idle:
    case Controller::RunState::Alarm:
    case Controller::RunState::EStop: pendingSteps_.clear(); break;
    }
}

void SessionWorker::userKey(int key) {
    lastError_.clear();
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    fileLoaded_ = false;
    keyPressed(controller_->operatorPanel().pressUserKey(key), QStringLiteral("K%1").arg(key), QStringLiteral("key-%1.nc").arg(key));
}

void SessionWorker::functionKey(int key) {
    lastError_.clear();
    if (busy()) {
        refuse(tr("A program is running: wait for it, or PAUSE / RESET first"));
        return;
    }
    fileLoaded_ = false;
    const bool hookRan = controller_->hasHook(config::Hook::ExtButton);
    if (!controller_->operatorPanel().loadFunctionKey(key)) {
        refuse(loadErrors());
        return;
    }
    if (controller_->start()) {
        activity_ = Activity::Hook;
        const QString name = QStringLiteral("FUNC K%1").arg(key, 2, 10, QLatin1Char('0'));
        log_->record(hookRan ? "hook" : "mdi", hookRan ? name + QStringLiteral(": ext_button.nc") : name);
    }
    publish();
}

// A press of a key wired to an input, as the controller read it: START and PAUSE act as the
// panel's own keys, an external key as a K key does (params 272-277 say what it does).
void SessionWorker::operatorKeys() {
    for (const controller::OperatorKey& key : controller_->operatorPanel().takeOperatorKeys()) {
        switch (key.kind) {
        case controller::OperatorKey::Kind::Start: start(); break;
        case controller::OperatorKey::Kind::Pause: pause(); break;
        case controller::OperatorKey::Kind::ExternKey: {
            const QString name = tr("External key %1").arg(key.key);
            if (busy()) {
                refuse(name + QStringLiteral(": ") + tr("A program is running: wait for it, or PAUSE / RESET first"));
                break;
            }
            lastError_.clear();
            fileLoaded_ = false;
            keyPressed(controller_->operatorPanel().pressExternKey(key.key), name, QStringLiteral("extnc%1-1.nc").arg(key.key - 1));
            break;
        }
        }
    }
}

void SessionWorker::keyPressed(const controller::KeyPress& press, const QString& key, const QString& hookFile) {
    switch (press.kind) {
    case controller::KeyPress::Kind::Hook:
        if (controller_->start()) {
            activity_ = Activity::Hook;
            log_->record("hook", key + QStringLiteral(": ") + hookFile);
        }
        break;
    case controller::KeyPress::Kind::Output:
        log_->record("output", key + QStringLiteral(": OUT%1").arg(press.value, 2, 10, QLatin1Char('0')));
        break;
    case controller::KeyPress::Kind::PanelKey: panelKey(key, press.value); return;
    case controller::KeyPress::Kind::Refused: refuse(QString::fromStdString(press.why.in(Language::messageLanguage()))); return;
    }
    publish();
}

// A K key set to a panel key code acts as that key, for the keys that act on the machine.
void SessionWorker::panelKey(const QString& key, int code) {
    switch (code) {
    case kGoWorkZero: // the Monitor page's softkey for all axes
        runHooks({goToWorkZeroStep({0, 1, 2})}, Activity::Mdi);
        return;
    case kGoHome: home({}); return;
    case kReset: reset(); return;
    case kStart: start(); return;
    case kPause: pause(); return;
    case kSpindle: spindleKey(0); return;
    case kM5: spindleKey(5); return;
    case kM4: spindleKey(4); return;
    case kM3: spindleKey(3); return;
    default: refuse(tr("%1 stands for the panel key %2, which this panel does not press for it").arg(key).arg(code));
    }
}

// Power-on: the machine folder's sysstart.nc runs before anything else; the boot homing prompt
// waits until it has ended (snapshots say homingPrompt only when nothing runs).
void SessionWorker::powerOn() {
    if (controller_->hasHook(config::Hook::PowerOn)) {
        runHooks({{config::Hook::PowerOn, {}, {}}}, Activity::Hook);
        return;
    }
    publish();
}

} // namespace m350::ui
