#include "ui/actions/ActionDispatcher.h"

#include "ui/actions/PanelKey.h"
#include "ui/actions/PanelScreen.h"
#include "ui/pages/Page.h"
#include "ui/pages/PanelPrompt.h"
#include "ui/session/MachineSession.h"

namespace m350::ui {

ActionDispatcher::ActionDispatcher(PanelScreen& screen, MachineSession& session, QObject* parent)
    : QObject(parent), screen_(screen), session_(session) {}

void ActionDispatcher::dispatch(const OperatorAction& action) {
    using Kind = OperatorAction::Kind;
    switch (action.kind) {
    case Kind::Wait: break;
    case Kind::Key:
    case Kind::KeyDown:
    case Kind::KeyUp: {
        const PanelKey* key = PanelKey::named(action.name);
        if (key && key->role == PanelKey::Role::Jog) {
            jogKey(*key, action.kind);
        } else if (action.kind != Kind::KeyUp && !machineKey(key)) {
            screenKey(key, action.name);
        }
        break;
    }
    case Kind::Softkey: screen_.pressSoftkey(action.softkey); break;
    case Kind::Text:
        if (screen_.prompt()->active()) {
            screen_.prompt()->type(action.text);
        } else {
            screen_.currentPage()->typed(action.text);
        }
        break;
    case Kind::Wheel:
        if (axisPresent(action.wheel.axis)) {
            session_.wheel(action.wheel.axis, action.wheel.step, action.wheel.detents, action.wheel.seconds);
        }
        break;
    case Kind::Page: screen_.showPage(action.name); break;
    case Kind::Force: force(action.force); break;
    case Kind::Language: screen_.setLanguage(action.name); break;
    case Kind::Load: session_.loadProgram(action.name); break;
    }
    emit dispatched(action);
}

// The keys that act on the machine whatever page is shown: what the key's table row says.
bool ActionDispatcher::machineKey(const PanelKey* key) {
    if (key && key->role == PanelKey::Role::Machine) {
        key->command(session_, key->argument);
        return true;
    }
    if (key && key->role == PanelKey::Role::JogStepInput) {
        screen_.askJogStep();
        return true;
    }
    if (key && key->role == PanelKey::Role::Wheel) {
        if (axisPresent(key->axis)) {
            screen_.switchWheel(key->axis, key->axis < 0 ? static_cast<int>(key->argument) : -1);
        }
        return true;
    }
    return false;
}

// A jog key held (key_down .. key_up) jogs while held; a plain key press is a tap: one step in
// STEP mode, a short nudge in CONT.
void ActionDispatcher::jogKey(const PanelKey& key, OperatorAction::Kind kind) {
    if (kind != OperatorAction::Kind::KeyUp && axisPresent(key.axis)) {
        session_.jogPress(key.axis, key.direction);
    }
    if (kind != OperatorAction::Kind::KeyDown) {
        session_.jogRelease(key.axis);
    }
}

// The 4th and 5th jog keys (and the wheel's 4th and 5th) move nothing on a machine without that
// axis: greyed out on the panel, and the same from the keyboard or a replay.
bool ActionDispatcher::axisPresent(int axis) const {
    SnapshotPtr snapshot = session_.latest();
    return !snapshot || axis < 0 || axis >= machine::kAxisCount ||
           snapshot->status.axisShown[static_cast<std::size_t>(axis)];
}

// Keys for the screen: the prompt first, then page keys and softkeys, then the current page.
void ActionDispatcher::screenKey(const PanelKey* key, const QString& name) {
    PanelPrompt* prompt = screen_.prompt();
    if (prompt->active()) {
        if (key && key->onPrompt) {
            key->onPrompt(*prompt);
        }
        return;
    }
    if (key && key->role == PanelKey::Role::Page) {
        screen_.showPage(key->page);
    } else if (key && key->role == PanelKey::Role::Softkey) {
        screen_.pressSoftkey(key->softkey);
    } else {
        screen_.currentPage()->key(name);
    }
}

void ActionDispatcher::force(const OperatorAction::Force& f) {
    using Fault = MachineSession::Fault;
    Fault fault = f.fault == QLatin1String("slow")       ? Fault::Slow
                  : f.fault == QLatin1String("bouncing") ? Fault::Bouncing
                  : f.fault == QLatin1String("none")     ? Fault::None
                  : f.fault == QLatin1String("pressed")  ? Fault::Pressed
                                                         : Fault::Stuck;
    session_.forceInput(f.input, fault, f.level, f.seconds);
}

} // namespace m350::ui
