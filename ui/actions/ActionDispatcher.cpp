#include "ui/actions/ActionDispatcher.h"

#include "ui/actions/PanelScreen.h"
#include "ui/pages/Page.h"
#include "ui/pages/PanelPrompt.h"
#include "ui/panel/KeyPad.h"
#include "ui/session/MachineSession.h"

#include <QHash>

namespace m350::ui {

ActionDispatcher::ActionDispatcher(PanelScreen& screen, MachineSession& session, QObject* parent)
    : QObject(parent), screen_(screen), session_(session) {}

void ActionDispatcher::dispatch(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    switch (action.kind) {
    case Kind::Wait: break;
    case Kind::Key:
    case Kind::KeyDown:
    case Kind::KeyUp:
        if (action.name.startsWith(QLatin1String("JOG_"))) {
            jogKey(action);
        } else if (action.kind != Kind::KeyUp && !machineKey(action)) {
            screenKey(action.name);
        }
        break;
    case Kind::Softkey: screen_.pressSoftkey(action.softkey); break;
    case Kind::Text:
        if (screen_.prompt()->active()) {
            screen_.prompt()->type(action.text);
        } else {
            screen_.currentPage()->typed(action.text);
        }
        break;
    case Kind::Wheel:
        session_.wheel(action.wheel.axis, action.wheel.step, action.wheel.detents, action.wheel.seconds);
        break;
    case Kind::Page: screen_.showPage(action.name); break;
    case Kind::Force: force(action.force); break;
    case Kind::Language: screen_.setLanguage(action.name); break;
    case Kind::Load: session_.loadProgram(action.name); break;
    }
    emit dispatched(action);
}

// The keys that act on the machine whatever page is shown.
bool ActionDispatcher::machineKey(const OperatorAction& action) {
    static const QHash<QString, double> steps{
        {"STEP_0.001", 0.001}, {"STEP_0.01", 0.01}, {"STEP_0.1", 0.1}, {"STEP_1", 1.0}};
    const QString& key = action.name;
    if (key == QLatin1String("START")) {
        session_.start();
    } else if (key == QLatin1String("PAUSE")) {
        session_.pause();
    } else if (key == QLatin1String("RESET")) {
        session_.reset();
    } else if (key == QLatin1String("ESTOP")) {
        session_.emergencyStop();
    } else if (key == QLatin1String("CONT_STEP_MPG")) {
        session_.cycleJogMode();
    } else if (key == QLatin1String("MPG_RUN")) {
        session_.toggleHandwheelGuide();
    } else if (key == QLatin1String("HIGH_LOW")) {
        session_.toggleJogHighSpeed();
    } else if (key == QLatin1String("SPINDLE")) {
        session_.spindleKey(0);
    } else if (KeyPad::mCodeKeys().contains(key)) {
        session_.spindleKey(key.mid(1).toInt());
    } else if (KeyPad::userKeys().contains(key)) {
        session_.userKey(key.mid(1).toInt());
    } else if (key.startsWith(QLatin1String("FRO_")) || key.startsWith(QLatin1String("SRO_"))) {
        QString how = key.mid(4);
        int step = how == QLatin1String("UP") ? 10 : how == QLatin1String("DOWN") ? -10 : 0;
        key.startsWith(QLatin1Char('F')) ? session_.feedOverrideKey(step) : session_.spindleOverrideKey(step);
    } else if (steps.contains(key)) {
        session_.setJogStep(steps.value(key));
    } else if (key == QLatin1String("STEP_INPUT")) {
        screen_.askJogStep();
    } else if (key == QLatin1String("EXT_START")) {
        session_.pressExternStart();
    } else {
        return false;
    }
    return true;
}

// A jog key held (key_down .. key_up) jogs while held; a plain key press is a tap: one step in
// STEP mode, a short nudge in CONT.
void ActionDispatcher::jogKey(const OperatorAction& action) {
    static const QString axes = QStringLiteral("XYZAB");
    int axis = static_cast<int>(axes.indexOf(action.name.at(4)));
    int direction = action.name.endsWith(QLatin1Char('+')) ? 1 : -1;
    if (action.kind != OperatorAction::Kind::KeyUp) {
        session_.jogPress(axis, direction);
    }
    if (action.kind != OperatorAction::Kind::KeyDown) {
        session_.jogRelease(axis);
    }
}

// Keys for the screen: the prompt first, then page keys, then the current page.
void ActionDispatcher::screenKey(const QString& name) {
    PanelPrompt* prompt = screen_.prompt();
    if (prompt->active()) {
        if (name == QLatin1String("ENTER")) {
            prompt->confirm();
        } else if (name == QLatin1String("ESC")) {
            prompt->cancel();
        } else if (name == QLatin1String("BACKSPACE")) {
            prompt->backspace();
        }
        return;
    }
    if (KeyPad::pageKeys().contains(name)) {
        screen_.showPage(KeyPad::pageKeys().value(name));
    } else if (name.size() == 2 && name.at(0) == QLatin1Char('F')) {
        screen_.pressSoftkey(name.mid(1).toInt());
    } else {
        screen_.currentPage()->key(name);
    }
}

void ActionDispatcher::force(const OperatorAction::Force& f) {
    using Fault = MachineSession::Fault;
    Fault fault = f.fault == QLatin1String("slow")       ? Fault::Slow
                  : f.fault == QLatin1String("bouncing") ? Fault::Bouncing
                  : f.fault == QLatin1String("none")     ? Fault::None
                                                         : Fault::Stuck;
    session_.forceInput(f.input, fault, f.level, f.seconds);
}

} // namespace m350::ui
